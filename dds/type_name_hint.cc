#include "dds/type_name_hint.h"

#include "core/json_diagnostic.h"

namespace arbc::dds {

std::string deployment_type_name(const std::string& dds_name) {
  std::string out;
  size_t start = 0;
  bool ros2 = false;
  for (;;) {
    size_t sep = dds_name.find("::", start);
    std::string part = dds_name.substr(start, sep == std::string::npos ? sep : sep - start);
    if (part == "dds_") {
      ros2 = true;
    } else {
      if (sep == std::string::npos && ros2 && !part.empty() && part.back() == '_') part.pop_back();
      out += (out.empty() ? "" : "/") + part;
    }
    if (sep == std::string::npos) return out;
    start = sep + 2;
  }
}

std::string type_name_hint(const Deployment& d, const std::string& port,
                           const std::string& spec_type, const std::string& remote) {
  std::string theirs = "\"" + deployment_type_name(remote) + "\"";
  if (spec_type.empty()) {
    return "; if the program's type is the same message, give " + port +
           " a named type in the spec and map it to " + theirs + " in the deployment's \"types\"";
  }
  auto mapped = d.types.find(spec_type);
  if (mapped == d.types.end() || d.path.empty()) {
    return "; this process names " + port + "'s type " + spec_type +
           " after the spec: if the program's type is the same message, add \"" + spec_type +
           "\": " + theirs + " to the deployment's \"types\"";
  }
  Diagnostic at = json_diagnostic(d.path, d.text, {"types", spec_type}, JsonPart::Key, "");
  std::string place = d.path;
  if (at.loc.line > 0)
    place += ":" + std::to_string(at.loc.line) + ":" + std::to_string(at.loc.column);
  return "; the name is the deployment's, " + place + " (\"" + spec_type + "\": \"" +
         mapped->second + "\", the type of " + port +
         "): if the program's type is the same message, write " + theirs + " there";
}

}  // namespace arbc::dds
