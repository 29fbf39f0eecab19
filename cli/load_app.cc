#include "cli/load_app.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "runtime/app_json.h"

namespace arbc::cli {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

LoadedApp load_app(const std::string& path) {
  LoadedApp out;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    std::filesystem::path manifest = std::filesystem::path(path) / "app.json";
    if (std::filesystem::exists(manifest, ec)) return load_app(manifest.string());
    out.diagnostics = path + ": error: is a directory without an app.json; give a spec or a built app\n";
    return out;
  }
  if (ends_with(path, ".spec")) {
    out.diagnostics = path + ": error: reading specs needs the compiler, which this build lacks\n";
    return out;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    out.diagnostics = path + ": error: cannot read the file\n";
    return out;
  }
  std::ostringstream text;
  text << in.rdbuf();
  model::AppLoad loaded = model::from_app_json(text.str());
  if (!loaded.ok) {
    out.diagnostics = path + ": error: " + loaded.error + "\n";
    return out;
  }
  out.ok = true;
  out.app = std::move(loaded.app);
  return out;
}

}  // namespace arbc::cli
