// Loads an application's core model from a spec (parse, check, lower) or a built app.json,
// for the commands that accept either (verify, docs, run).
#pragma once

#include <string>
#include <vector>

#include "runtime/app_model.h"

namespace arbc::cli {

struct LoadedApp {
  bool ok = false;
  model::App app;
  std::string diagnostics;            // rendered, ready for stderr, when !ok
  std::vector<std::string> verdicts;  // filled by commands that verify
};

LoadedApp load_app(const std::string& path);

}  // namespace arbc::cli
