// Loading a built app directory (app.json + monitors/*.lua) and checking it against the
// module registry before anything runs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"
#include "runtime/module.h"
#include "runtime/transport.h"

namespace arbc {

// Reads DIR/app.json and checks that every monitor file it names exists and has the bytes
// whose SHA-256 app.json records (core/monitor_digests.h). On failure nullopt and *err: one
// line per problem, each naming the file and saying what to do. When app.json's own text is
// at fault (not JSON, a value it cannot hold), *err is "FILE:LINE:COL: what is wrong" and
// *placed, when given, is the same error as a diagnostic, to render with the line quoted.
std::optional<model::App> load_app_dir(const std::string& dir, std::string* err,
                                       Diagnostic* placed = nullptr);

// Checks that each module of the app that this process hosts is registered and declares the
// app's ports with the same direction and type (same_type). Returns one message per problem;
// empty when fine.
std::vector<std::string> check_modules(const model::App& app, const std::string& app_file,
                                       const Registry& registry = Registry::global(),
                                       const ModuleSet& hosted = ModuleSet::everything());

}  // namespace arbc
