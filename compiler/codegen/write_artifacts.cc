#include "compiler/codegen/write_artifacts.h"

#include <cstdio>
#include <filesystem>

namespace arbc::codegen {

namespace fs = std::filesystem;

std::string write_artifacts(const std::string& out_dir, const std::string& app_name,
                            const std::vector<OutputFile>& files) {
  std::error_code ec;
  fs::path target = fs::path(out_dir) / app_name;
  fs::path staging = fs::path(out_dir) / ("." + app_name + ".arbc-tmp");
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec))
      return "'" + target.string() + "' exists and is not a directory; remove it or choose -o";
    if (!fs::is_empty(target, ec) && !fs::exists(target / "app.json", ec))
      return "refusing to replace '" + target.string() +
             "': it is not empty and has no app.json (not an arbc build); choose another -o";
  }
  fs::remove_all(staging, ec);
  if (!fs::create_directories(staging, ec) && ec)
    return "cannot create '" + staging.string() + "': " + ec.message();
  fs::path made;  // the last directory created: monitors come in a row
  for (const OutputFile& f : files) {
    fs::path path = staging / f.path;
    if (path.parent_path() != made) {
      fs::create_directories(path.parent_path(), ec);
      made = path.parent_path();
    }
    std::FILE* out = std::fopen(path.c_str(), "wb");
    bool ok = out && std::fwrite(f.content.data(), 1, f.content.size(), out) == f.content.size();
    if (out && std::fclose(out) != 0) ok = false;
    if (!ok) {
      fs::remove_all(staging, ec);
      return "cannot write '" + (target / f.path).string() + "'";
    }
  }
  fs::remove_all(target, ec);
  if (ec) return "cannot replace '" + target.string() + "': " + ec.message();
  fs::rename(staging, target, ec);
  if (ec) return "cannot move the build into '" + target.string() + "': " + ec.message();
  return {};
}

}  // namespace arbc::codegen
