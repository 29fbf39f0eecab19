#include "runtime/app_loader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/app_json.h"
#include "core/join.h"
#include "core/monitor_digests.h"

namespace arbc {

namespace fs = std::filesystem;

namespace {

// The app directories right under dir (sorted), as `arbc build -o dir` leaves them.
std::vector<std::string> app_dirs_in(const std::string& dir) {
  std::vector<std::string> apps;
  std::error_code ec;  // a directory that changes under the walk ends it, without an exception
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code ignored;
    if (it->is_directory(ignored) && fs::is_regular_file(it->path() / "app.json", ignored))
      apps.push_back(it->path().string());
  }
  std::sort(apps.begin(), apps.end());
  return apps;
}

}  // namespace

std::optional<model::App> load_app_dir(const std::string& dir, std::string* err,
                                       Diagnostic* placed) {
  fs::path file = fs::path(dir) / "app.json";
  std::ifstream in(file, std::ios::binary);
  if (!fs::is_directory(dir)) {
    *err = dir +
           ": not a directory; give the directory `arbc build` wrote (it holds app.json and "
           "monitors/)";
    return std::nullopt;
  }
  std::error_code ec;
  if (!in && fs::exists(fs::path(dir) / "ports.json", ec)) {
    // `arbc build --target yarp` writes no app.json: the application runs on YARP.
    *err = dir +
           ": a build for YARP (arbc build --target yarp), which runs on YARP "
           "(docs/yarp.md#deploying-a-spec-on-yarp-step-by-step) and has no app.json; to run "
           "on arbc's runtime, build the spec without --target yarp";
    return std::nullopt;
  }
  if (!in) {
    *err =
        file.string() + ": cannot read; is " + dir + " an app directory written by `arbc build`?";
    // `arbc build -o OUT` writes OUT/APP/: the directory given is often OUT.
    std::vector<std::string> apps = app_dirs_in(dir);
    if (apps.size() > 3) {
      size_t more = apps.size() - 3;
      apps.resize(3);
      apps.push_back(std::to_string(more) + " more");
    }
    if (!apps.empty()) *err += " It holds " + join(apps, ", ", " and ") + ".";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  Diagnostic error;
  std::optional<model::App> app = model::from_app_json(text.str(), file.string(), &error);
  if (!app) {
    // One rebuild hint: the model's own error may already carry one (a newer schema).
    if (error.message.find("rebuild") == std::string::npos)
      error.message += " (rebuild it with `arbc build`)";
    *err = file.string();
    if (error.loc.line > 0)
      *err += ":" + std::to_string(error.loc.line) + ":" + std::to_string(error.loc.column);
    *err += ": " + error.message;
    if (placed) *placed = std::move(error);
    return std::nullopt;
  }
  // Every monitor exists and has the bytes `arbc build` wrote (the digests in app.json).
  std::vector<std::string> problems = model::check_monitor_files(*app, dir);
  if (!problems.empty()) {
    *err = join(problems, "\n");
    return std::nullopt;
  }
  return app;
}

std::vector<std::string> check_modules(const model::App& app, const std::string& app_file,
                                       const Registry& registry, const ModuleSet& hosted) {
  std::vector<std::string> errors;
  for (const model::Module& m : app.modules) {
    if (!hosted.contains(m.name)) continue;  // runs in another process: not needed here
    const ModuleFactory* factory = registry.find_module(m.name);
    if (!factory) {
      std::string known = join(registry.module_names());
      // At the module's declaration in the spec when app.json records it: the app.json of
      // `arbc run SPEC` is in a scratch directory that is gone when the message is read.
      std::string where = app_file;
      if (!m.loc.file.empty() && m.loc.line > 0)
        where = m.loc.file + ":" + std::to_string(m.loc.line) + ":" + std::to_string(m.loc.column);
      errors.push_back(where + ": module '" + m.name +
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
