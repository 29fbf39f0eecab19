#include "core/file_name.h"

#include <mutex>
#include <unordered_set>

namespace arbc::model {

namespace {

// The interned paths. Node-based, so an element's address stays valid as the set grows; never
// destroyed, so a location read during static destruction still has its path. Locked: the
// language server builds locations on several threads.
struct InternedPaths {
  std::mutex mutex;
  std::unordered_set<std::string> paths;
};

InternedPaths& interned_paths() {
  static auto* paths = new InternedPaths;
  return *paths;
}

}  // namespace

FileName::FileName(std::string_view path) {
  if (path.empty()) return;
  InternedPaths& interned = interned_paths();
  std::lock_guard<std::mutex> lock(interned.mutex);
  path_ = &*interned.paths.emplace(path).first;
}

const std::string& FileName::empty_path() {
  static const std::string empty;
  return empty;
}

}  // namespace arbc::model
