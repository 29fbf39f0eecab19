#include "import/yarp/xml_mismatch.h"

#include <cstring>
#include <vector>

namespace arbc::yarp {
namespace {

struct OpenTag {
  std::string name;
  int line = 0, column = 0;
};

bool name_char(char c) { return c && !std::strchr(" \t\r\n/>", c); }

}  // namespace

std::optional<XmlMismatch> find_xml_mismatch(const std::string& text) {
  size_t i = 0;
  int line = 1;
  size_t line_start = 0;
  auto advance_to = [&](size_t to) {
    for (; i < to && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
  };
  // Skips a construct that ends with `end`; false when it never ends.
  auto skip_past = [&](const char* end) {
    size_t e = text.find(end, i);
    if (e == std::string::npos) return false;
    advance_to(e + std::strlen(end));
    return true;
  };
  std::vector<OpenTag> open;
  while (i < text.size()) {
    if (text[i] != '<') {
      advance_to(i + 1);
      continue;
    }
    int tag_line = line, tag_column = static_cast<int>(i - line_start) + 1;
    if (text.compare(i, 4, "<!--") == 0) {
      if (!skip_past("-->")) break;
    } else if (text.compare(i, 9, "<![CDATA[") == 0) {
      if (!skip_past("]]>")) break;
    } else if (text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0) {
      if (!skip_past(">")) break;
    } else {
      bool closing = i + 1 < text.size() && text[i + 1] == '/';
      size_t n = i + (closing ? 2 : 1), b = n;
      while (n < text.size() && name_char(text[n])) ++n;
      std::string name = text.substr(b, n - b);
      size_t gt = text.find('>', n);
      if (gt == std::string::npos) break;
      bool self_closing = text[gt - 1] == '/';
      advance_to(gt + 1);
      if (closing) {
        if (open.empty() || open.back().name != name) {
          XmlMismatch m{tag_line, tag_column, "</" + name + ">", "", 0};
          if (!open.empty()) {
            m.open = "<" + open.back().name + ">";
            m.open_line = open.back().line;
          }
          return m;
        }
        open.pop_back();
      } else if (!self_closing) {
        open.push_back({name, tag_line, tag_column});
      }
    }
  }
  if (open.empty()) return std::nullopt;
  const OpenTag& o = open.back();
  return XmlMismatch{o.line, o.column, "", "<" + o.name + ">", o.line};
}

}  // namespace arbc::yarp
