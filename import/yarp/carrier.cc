#include "import/yarp/carrier.h"

namespace arbc::yarp {

bool parse_carrier(std::string_view text, Carrier* out, std::string* err) {
  Carrier c;
  if (text.empty()) {
    *out = c;
    return true;
  }
  size_t plus = text.find('+');
  c.base = std::string(text.substr(0, plus));
  if (c.base.empty()) {
    *err = "the carrier '" + std::string(text) + "' starts with '+': name the carrier (tcp)";
    return false;
  }
  while (plus != std::string_view::npos) {
    size_t next = text.find('+', plus + 1);
    std::string_view part = text.substr(
        plus + 1, next == std::string_view::npos ? std::string_view::npos : next - plus - 1);
    plus = next;
    size_t dot = part.find('.');
    std::string key(part.substr(0, dot));
    std::string value(dot == std::string_view::npos ? "" : part.substr(dot + 1));
    if (key.empty()) {
      *err = "the carrier '" + std::string(text) + "' has an empty modifier";
      return false;
    }
    if (value.find('.') != std::string::npos) {
      *err = "in the carrier '" + std::string(text) + "', YARP reads `" + key + "." + value +
             "` as several words (every '.' becomes a space): " +
             (key == "file" ? "name the file without its .lua extension, and without dots"
                            : "use a value without dots");
      return false;
    }
    c.modifiers.emplace_back(key, value);
    if (key == "recv" && value == "portmonitor") c.monitor = true;
    if (key == "send" && value == "portmonitor") c.send_monitor = true;
    if (key == "type") c.type = value;
    if (key == "file") c.file = value;
    if (key == "context") c.context = value;
    if (key == "constraint") c.constraint = value;
  }
  if ((c.monitor || c.send_monitor) && c.file.empty()) c.file = "modifier";  // YARP's default
  *out = c;
  return true;
}

}  // namespace arbc::yarp
