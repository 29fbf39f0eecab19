#include "runtime/app_loader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/app_json.h"
#include "core/join.h"
#include "core/monitor_digests.h"

namespace arbc {

namespace fs = std::filesystem;

AppDirLoad load_app_dir(const std::string& dir) {
  AppDirLoad load;
  load.dir = dir;
  fs::path file = fs::path(dir) / "app.json";
  std::ifstream in(file, std::ios::binary);
  if (!fs::is_directory(dir)) {
    load.errors.push_back(dir +
                          ": not a directory; give the directory `arbc build` wrote "
                          "(it holds app.json and monitors/)");
    return load;
  }
  if (!in) {
    load.errors.push_back(file.string() + ": cannot read; is " + dir +
                          " an app directory written by `arbc build`?");
    return load;
  }
  std::ostringstream text;
  text << in.rdbuf();
  model::AppLoad parsed = model::from_app_json(text.str());
  if (!parsed.ok) {
    // One rebuild hint: the model's own error may already carry one (a newer schema).
    std::string hint =
        parsed.error.find("rebuild") == std::string::npos ? " (rebuild it with `arbc build`)" : "";
    load.errors.push_back(file.string() + ": " + parsed.error + hint);
    return load;
  }
  // Every monitor exists and has the bytes `arbc build` wrote (the digests in app.json).
  load.errors = model::check_monitor_files(parsed.app, dir);
  load.app = std::move(parsed.app);
  load.ok = load.errors.empty();
  return load;
}

std::vector<std::string> check_modules(const model::App& app, const std::string& app_file,
                                       const Registry& registry, const ModuleSet& hosted) {
  std::vector<std::string> errors;
  for (const model::Module& m : app.modules) {
    if (!hosted.contains(m.name)) continue;  // runs in another process: not needed here
    const ModuleFactory* factory = registry.find_module(m.name);
    if (!factory) {
      std::string known = join(registry.module_names());
      errors.push_back(app_file + ": module '" + m.name +
                       "' is not registered; load the plugin that provides it with --plugin LIB" +
                       " (registered: " + (known.empty() ? "none" : known) + ")");
      continue;
    }
    std::unique_ptr<Module> instance = (*factory)();
    for (const model::Port& p : m.ports) {
      const PortDecl* decl = nullptr;
      for (const PortDecl& d : instance->ports()) {
        if (d.name == p.name) decl = &d;
      }
      std::string where = app_file + ": port " + m.name + "." + p.name;
      const char* want = p.direction == model::Direction::In ? "in" : "out";
      if (!decl) {
        errors.push_back(where + " (" + want + " " + p.type->to_string() +
                         ") is not declared by the registered module " + m.name +
                         "; declare it in the module's constructor or fix the spec");
        continue;
      }
      if (decl->is_input != (p.direction == model::Direction::In)) {
        errors.push_back(where + " is '" + want + "' in the app but '" +
                         (decl->is_input ? "in" : "out") + "' in the module");
      }
      std::string type_error;
      TypePtr declared = parse_type(decl->type, &type_error);
      if (!declared) {
        errors.push_back(where + ": the module declares an invalid type \"" + decl->type +
                         "\": " + type_error);
      } else if (!same_type(*declared, *p.type)) {
        errors.push_back(where + " has type " + p.type->to_string() +
                         " in the app but the module declares " + declared->to_string());
      }
    }
  }
  return errors;
}

}  // namespace arbc
