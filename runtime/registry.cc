// The module/environment registry and plugin loading.
#include <dlfcn.h>

#include "runtime/module.h"

namespace arbc {

Registry& Registry::global() {
  static Registry registry;
  return registry;
}

bool Registry::add_module(std::string name, ModuleFactory factory) {
  if (modules_.count(name)) {
    errors_.push_back("module '" + name + "' is registered twice; the first registration is used");
    return false;
  }
  modules_.emplace(std::move(name), std::move(factory));
  return true;
}

bool Registry::add_environment(std::string name, EnvironmentFactory factory) {
  if (environments_.count(name)) {
    errors_.push_back("environment '" + name +
                      "' is registered twice; the first registration is used");
    return false;
  }
  environments_.emplace(std::move(name), std::move(factory));
  return true;
}

const ModuleFactory* Registry::find_module(std::string_view name) const {
  auto it = modules_.find(name);
  return it == modules_.end() ? nullptr : &it->second;
}

const EnvironmentFactory* Registry::find_environment(std::string_view name) const {
  auto it = environments_.find(name);
  return it == environments_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::module_names() const {
  std::vector<std::string> names;
  for (const auto& [name, _] : modules_) names.push_back(name);
  return names;
}

std::vector<std::string> Registry::environment_names() const {
  std::vector<std::string> names;
  for (const auto& [name, _] : environments_) names.push_back(name);
  return names;
}

bool load_plugin(const std::string& path, std::string* err) {
  Registry& host = Registry::global();
  size_t before = host.module_names().size() + host.environment_names().size();
  // A bare file name would make dlopen search the library path; a plugin is a file.
  std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    *err = std::string("cannot load plugin: ") + (why ? why : path);
    return false;
  }
  // A plugin that links arbc_runtime statically has its own Registry::global() unless the
  // host exports its copy (then the dynamic linker binds the plugin to it). When they
  // differ, copy the plugin's registrations into the host's registry. The library stays
  // loaded for the life of the process, so its factories stay valid.
  using GlobalFn = Registry& (*)();
  auto plugin_global = reinterpret_cast<GlobalFn>(dlsym(handle, "_ZN4arbc8Registry6globalEv"));
  if (plugin_global && &plugin_global() != &host) {
    Registry& theirs = plugin_global();
    for (const std::string& name : theirs.module_names()) {
      host.add_module(name, *theirs.find_module(name));
    }
    for (const std::string& name : theirs.environment_names()) {
      host.add_environment(name, *theirs.find_environment(name));
    }
  }
  size_t after = host.module_names().size() + host.environment_names().size();
  if (after == before) {
    *err = "plugin " + path +
           " registered no module or environment (use ARBC_REGISTER_MODULE in its sources, "
           "or it was already loaded)";
    return false;
  }
  return true;
}

}  // namespace arbc
