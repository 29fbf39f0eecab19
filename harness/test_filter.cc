#include "harness/test_filter.h"

#include <fnmatch.h>

namespace arbc::harness {

bool filter_matches(const std::string& glob, const std::string& name) {
  return fnmatch(glob.c_str(), name.c_str(), 0) == 0;
}

std::string filter_matched_none(const std::string& glob, const std::vector<std::string>& names) {
  std::string out = "--filter '" + glob + "' matches none of the " + std::to_string(names.size()) +
                    " test" + (names.size() == 1 ? "" : "s") + " (a glob over the whole name)";
  std::string part = "*" + glob + "*";
  for (const std::string& name : names) {
    if (filter_matches(part, name)) return out + "; did you mean --filter '" + part + "'?";
  }
  out += "; the tests are:";
  for (size_t i = 0; i < names.size() && i < 10; ++i) out += "\n  " + names[i];
  if (names.size() > 10) out += "\n  ... " + std::to_string(names.size() - 10) + " more";
  return out;
}

}  // namespace arbc::harness
