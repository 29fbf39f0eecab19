// Loading a built app directory (app.json + monitors/*.lua) and checking it against the
// module registry before anything runs.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/module.h"
#include "runtime/transport.h"

namespace arbc {

struct AppDirLoad {
  bool ok = false;
  model::App app;
  std::string dir;
  std::vector<std::string> errors;  // each names the file and says what to do
};

// Reads DIR/app.json and checks that every monitor file it names exists and has the bytes
// whose SHA-256 app.json records (core/monitor_digests.h).
AppDirLoad load_app_dir(const std::string& dir);

// Checks that each module of the app that this process hosts is registered and declares the
// app's ports with the same direction and type (same_type). Returns one message per problem;
// empty when fine.
std::vector<std::string> check_modules(const model::App& app, const std::string& app_file,
                                       const Registry& registry = Registry::global(),
                                       const ModuleSet& hosted = ModuleSet::everything());

}  // namespace arbc
