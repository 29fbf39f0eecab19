#include "import/yarp/script_locator.h"

#include <cstdlib>
#include <filesystem>

namespace arbc::yarp {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split_dirs(const char* value) {
  std::vector<std::string> out;
  std::string s = value ? value : "";
  size_t start = 0;
  while (start <= s.size()) {
    size_t colon = s.find(':', start);
    std::string part =
        s.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    if (!part.empty()) out.push_back(part);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return out;
}

std::string display(const fs::path& p) { return p.lexically_normal().generic_string(); }

}  // namespace

ScriptLookup locate_script(const std::string& name, const std::string& context,
                           const std::string& xml_file,
                           const std::vector<std::string>& search_paths) {
  std::vector<fs::path> roots;
  for (const std::string& dir : search_paths) roots.emplace_back(dir);
  fs::path xml_dir = fs::path(xml_file).parent_path();
  roots.push_back(xml_dir.empty() ? fs::path(".") : xml_dir);
  if (const char* home = std::getenv("YARP_DATA_HOME"); home && *home) roots.emplace_back(home);
  for (const std::string& dir : split_dirs(std::getenv("YARP_DATA_DIRS"))) roots.emplace_back(dir);

  ScriptLookup out;
  for (const fs::path& root : roots) {
    std::vector<fs::path> places;
    if (!context.empty()) places.push_back(root / "contexts" / context);
    places.push_back(root);
    for (const fs::path& place : places) {
      for (const std::string& file : {name, name + ".lua"}) {
        fs::path candidate = place / file;
        out.tried.push_back(display(candidate));
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec)) {
          out.found = display(candidate);
          return out;
        }
      }
    }
  }
  return out;
}

}  // namespace arbc::yarp
