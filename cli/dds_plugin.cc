#include "cli/dds_plugin.h"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

#include "dds/transport_plugin.h"

namespace arbc::cli {

namespace {

namespace fs = std::filesystem;

// Where the plugin may be, nearest first.
std::vector<fs::path> plugin_candidates() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  fs::path dir = exe.parent_path();
  return {dir / ARBC_DDS_PLUGIN_FILE, dir.parent_path() / "lib" / "arbc" / ARBC_DDS_PLUGIN_FILE};
}

// The loaded plugin, or nullptr and *err. It stays loaded for the life of the process: the
// transport's code and its Fast-DDS threads live in it.
void* open_plugin(std::string* err) {
  std::string looked;
  for (const fs::path& file : plugin_candidates()) {
    std::error_code ec;
    if (!fs::exists(file, ec)) {
      looked += (looked.empty() ? "" : ", ") + file.string();
      continue;
    }
    // RTLD_GLOBAL is not needed: the plugin binds to the runtime this executable exports.
    if (void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL)) return handle;
    const char* why = dlerror();
    *err = "cannot load the DDS transport " + file.string() + ": " + (why ? why : "unknown") +
           " (is Fast-DDS 2.9 installed? scripts/install-deps.sh installs it)";
    return nullptr;
  }
  *err = "the DDS transport " ARBC_DDS_PLUGIN_FILE " is not installed (looked in " + looked +
         "); install arbc again (cmake --install puts it in <prefix>/lib/arbc)";
  return nullptr;
}

// The plugin, loaded once and checked to come from this build; nullptr and *err otherwise.
void* checked_plugin(std::string* err) {
  static void* handle = nullptr;
  if (handle) return handle;
  void* opened = open_plugin(err);
  if (!opened) return nullptr;
  using SignatureFn = const char* (*)();
  auto signature = reinterpret_cast<SignatureFn>(dlsym(opened, "arbc_dds_plugin_signature"));
  if (!signature) {
    *err = "the DDS transport " ARBC_DDS_PLUGIN_FILE " lacks its entry points (not an arbc plugin)";
    return nullptr;
  }
  if (dds::plugin_signature() != signature()) {
    *err = "the DDS transport " ARBC_DDS_PLUGIN_FILE " was built for another arbc (" +
           std::string(signature()) + ", this is " + dds::plugin_signature() +
           "): install both from one build";
    return nullptr;
  }
  return handle = opened;
}

// An entry point of the checked plugin; nullptr and *err when it lacks it.
template <class Fn>
Fn entry(const char* name, std::string* err) {
  void* handle = checked_plugin(err);
  if (!handle) return nullptr;
  auto fn = reinterpret_cast<Fn>(dlsym(handle, name));
  if (!fn)
    *err = "the DDS transport " ARBC_DDS_PLUGIN_FILE " lacks its entry point " + std::string(name) +
           " (not an arbc plugin of this build)";
  return fn;
}

}  // namespace

std::unique_ptr<Transport> load_dds_transport(const model::App& app, dds::DdsOptions options,
                                              std::string* err) {
  using MakeFn = Transport* (*)(const model::App*, dds::DdsOptions*);
  auto make = entry<MakeFn>("arbc_dds_plugin_make_transport", err);
  if (!make) return nullptr;
  return std::unique_ptr<Transport>(make(&app, &options));
}

bool read_dds_status(int domain, const std::string& topic, double wait,
                     std::vector<Value>* statuses, std::string* note, std::string* err) {
  using ReadFn =
      bool (*)(int, const std::string*, double, std::vector<Value>*, std::string*, std::string*);
  auto read = entry<ReadFn>("arbc_dds_plugin_read_status", err);
  return read && read(domain, &topic, wait, statuses, note, err);
}

}  // namespace arbc::cli
