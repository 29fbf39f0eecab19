// Code-generation targets (docs/design.md#code-generation-targets). A target turns a lowered
// application into the files of its artifact directory. `embedded` (the default) writes app.json
// and one Lua monitor per connection for the bundled runtime; `yarp` writes a yarpmanager
// application with monitors for YARP's portmonitor carrier (yarp_target.h).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.h"

namespace arbc::lower {
struct LoweredApp;
}

namespace arbc::codegen {

// One generated file, its path relative to the application's directory ("app.json",
// "monitors/PickAndPlace.cmd__take.lua").
struct OutputFile {
  std::string path;
  std::string content;
};

struct CodegenResult {
  bool ok = false;
  // Not ok because of the input (exit 2: what the target cannot carry, names that clash), not
  // because of a bug in arbc (exit 3: a generated monitor that is not valid Lua).
  bool bad_input = false;
  std::vector<OutputFile> files;  // in a fixed order; the same input gives the same bytes
  std::vector<Diagnostic> diagnostics;
};

// What a deployment file (`arbc build --deploy FILE`) tells a target.
struct TargetOptions {
  std::map<std::string, std::string> port_names;  // "Module.port" -> the middleware's name
};

class Target {
 public:
  virtual ~Target() = default;
  // Takes the deployment's options; false (and `err`) when the target has no use for them.
  virtual bool configure(const TargetOptions& options, std::string* err) {
    if (options.port_names.empty()) return true;
    *err =
        "the " + std::string(name()) + " target does not name ports; --deploy is for --target yarp";
    return false;
  }
  virtual std::string_view name() const = 0;
  virtual std::string_view description() const = 0;  // one line, for --help
  // Generates every file. Deterministic; never throws for a checked, lowered application.
  virtual CodegenResult generate(const lower::LoweredApp& app) const = 0;
};

inline constexpr std::string_view kDefaultTarget = "embedded";

// The target called `name`, or null when there is none (list them with target_names()).
std::unique_ptr<Target> make_target(std::string_view name);

// Every registered target's name, in registry order.
std::vector<std::string> target_names();

}  // namespace arbc::codegen
