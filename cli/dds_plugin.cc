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

}  // namespace

std::unique_ptr<Transport> load_dds_transport(const model::App& app, dds::DdsOptions options,
                                              std::string* err) {
  static void* handle = nullptr;
  if (!handle && !(handle = open_plugin(err))) return nullptr;
  using SignatureFn = const char* (*)();
  using MakeFn = Transport* (*)(const model::App*, dds::DdsOptions*);
  auto signature = reinterpret_cast<SignatureFn>(dlsym(handle, "arbc_dds_plugin_signature"));
  auto make = reinterpret_cast<MakeFn>(dlsym(handle, "arbc_dds_plugin_make_transport"));
  if (!signature || !make) {
    *err = "the DDS transport " ARBC_DDS_PLUGIN_FILE " lacks its entry points (not an arbc plugin)";
    return nullptr;
  }
  if (dds::plugin_signature() != signature()) {
    *err = "the DDS transport " ARBC_DDS_PLUGIN_FILE " was built for another arbc (" +
           std::string(signature()) + ", this is " + dds::plugin_signature() +
           "): install both from one build";
    return nullptr;
  }
  return std::unique_ptr<Transport>(make(&app, &options));
}

}  // namespace arbc::cli
