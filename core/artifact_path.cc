#include "core/artifact_path.h"

#include <filesystem>
#include <system_error>

namespace arbc {

namespace fs = std::filesystem;

std::string artifact_path(std::string_view path, std::string_view working_directory) {
  fs::path p(path);
  if (!p.is_absolute()) return std::string(path);
  fs::path base = fs::path(working_directory).lexically_normal();
  if (!base.has_filename() && base.has_parent_path() && base != base.root_path())
    base = base.parent_path();  // "/a/b/" is the folder "/a/b"
  fs::path relative = p.lexically_normal().lexically_relative(base);
  bool under = !relative.empty() && *relative.begin() != ".." && relative != ".";
  return under ? relative.generic_string() : p.filename().generic_string();
}

std::string artifact_path(std::string_view path) {
  fs::path p(path);
  if (!p.is_absolute()) return std::string(path);
  std::error_code ec;
  fs::path here = fs::current_path(ec);
  return ec ? p.filename().generic_string() : artifact_path(path, here.string());
}

ArtifactPaths::ArtifactPaths() {
  std::error_code ec;
  fs::path here = fs::current_path(ec);
  if (!ec) working_directory_ = here.string();
}

const std::string& ArtifactPaths::operator()(const std::string& path) {
  if (!fs::path(path).is_absolute()) return path;  // most paths: nothing to look up
  auto it = mapped_.find(path);
  if (it == mapped_.end()) {
    std::string name = working_directory_.empty() && fs::path(path).is_absolute()
                           ? fs::path(path).filename().generic_string()
                           : artifact_path(path, working_directory_);
    it = mapped_.emplace(path, std::move(name)).first;
  }
  return it->second;
}

}  // namespace arbc
