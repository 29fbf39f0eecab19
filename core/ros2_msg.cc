#include "core/ros2_msg.h"

#include <cctype>
#include <charconv>
#include <set>

namespace arbc::ros2 {

namespace {

const std::set<std::string, std::less<>>& primitives() {
  static const std::set<std::string, std::less<>> names = {
      "bool",   "byte",  "char",   "float32", "float64", "int8",   "uint8",  "int16",
      "uint16", "int32", "uint32", "int64",   "uint64",  "string", "wstring"};
  return names;
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A whole positive decimal number; nullopt otherwise.
std::optional<int> size_of(std::string_view text) {
  int n = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n <= 0) return std::nullopt;
  return n;
}

// The type word (`float64[<=3]`, `geometry_msgs/Point`, `string<=10`) into *out; else why not.
std::string parse_type(std::string_view word, const std::string& package, MsgType* out) {
  std::string_view base = word;
  if (size_t open = word.find('['); open != std::string_view::npos) {
    if (word.back() != ']') return "an array type ends with ']'";
    std::string_view inside = word.substr(open + 1, word.size() - open - 2);
    base = word.substr(0, open);
    if (inside.empty()) {
      out->array = MsgType::Array::Sequence;
    } else {
      bool bounded = inside.substr(0, 2) == "<=";
      std::optional<int> n = size_of(bounded ? inside.substr(2) : inside);
      if (!n) return "an array's size is a positive whole number: T[N], T[<=N] or T[]";
      out->array = bounded ? MsgType::Array::BoundedSequence : MsgType::Array::Fixed;
      out->array_size = *n;
    }
  }
  if (size_t bound = base.find("<="); bound != std::string_view::npos) {
    std::string_view s = base.substr(0, bound);
    std::optional<int> n = size_of(base.substr(bound + 2));
    if ((s != "string" && s != "wstring") || !n)
      return "only strings are bounded, as string<=N with N a positive whole number";
    out->name = std::string(s);
    out->string_bound = *n;
    return "";
  }
  if (primitives().count(base)) {
    out->name = std::string(base);
    return "";
  }
  std::string_view pkg = package, type = base;
  if (size_t slash = base.find('/'); slash != std::string_view::npos) {
    pkg = base.substr(0, slash);
    type = base.substr(slash + 1);
    if (type.substr(0, 4) == "msg/") type = type.substr(4);
  }
  bool ok = !pkg.empty() && !type.empty() && std::isupper(static_cast<unsigned char>(type[0]));
  for (char c : pkg) ok &= is_name_char(c);
  for (char c : type) ok &= is_name_char(c);
  if (!ok)
    return "'" + std::string(base) +
           "' is not a type: a primitive (bool, int32, float64, string, ...) or a message "
           "(Name, or pkg/Name)";
  out->primitive = false;
  out->name = std::string(pkg) + "/msg/" + std::string(type);
  return "";
}

// The line without its comment (a `#` outside double or single quotes).
std::string_view without_comment(std::string_view line) {
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (quote) {
      if (c == '\\')
        ++i;
      else if (c == quote)
        quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#') {
      return line.substr(0, i);
    }
  }
  return line;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

struct Line {
  std::string_view text;  // without comment, trimmed
  int number = 0, column = 0;
};

// One field or constant line into `def`; "" or why not (*column: where).
std::string parse_line(const Line& l, const std::string& package, MsgDefinition* def, int* column) {
  size_t space = l.text.find_first_of(" \t");
  std::string_view type_word = l.text.substr(0, space);
  *column = l.column;
  MsgType type;
  std::string why = parse_type(type_word, package, &type);
  if (!why.empty()) return why;
  if (space == std::string_view::npos) return "a field has a type and a name: TYPE NAME";
  std::string_view rest = trim(l.text.substr(space));
  *column = l.column + static_cast<int>(rest.data() - l.text.data());
  size_t end = 0;
  while (end < rest.size() && is_name_char(rest[end])) ++end;
  std::string name(rest.substr(0, end));
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0])))
    return "a field or constant name starts with a letter";
  std::string_view after = trim(rest.substr(end));
  if (!after.empty() && after[0] == '=') {
    std::string value(trim(after.substr(1)));
    if (value.empty()) return "a constant has a value: TYPE NAME=VALUE";
    if (type.array != MsgType::Array::None) return "a constant cannot be an array";
    def->constants.push_back({name, type, value, l.number, l.column});
    return "";
  }
  for (const MsgField& f : def->fields)
    if (f.name == name) return "field '" + name + "' is declared twice";
  def->fields.push_back({name, type, std::string(after), l.number, l.column});
  return "";
}

}  // namespace

std::string MsgType::text() const {
  std::string out = name;
  if (!primitive && name.find("/msg/") != std::string::npos)
    out = name.substr(0, name.find("/msg/")) + "/" + name.substr(name.find("/msg/") + 5);
  if (string_bound) out += "<=" + std::to_string(string_bound);
  switch (array) {
    case Array::None:
      break;
    case Array::Sequence:
      out += "[]";
      break;
    case Array::BoundedSequence:
      out += "[<=" + std::to_string(array_size) + "]";
      break;
    case Array::Fixed:
      out += "[" + std::to_string(array_size) + "]";
      break;
  }
  return out;
}

std::optional<std::pair<std::string, std::string>> split_message_name(std::string_view name) {
  std::string_view pkg, type;
  if (size_t colons = name.find("::msg::dds_::"); colons != std::string_view::npos) {
    pkg = name.substr(0, colons);
    type = name.substr(colons + 13);
    if (type.empty() || type.back() != '_') return std::nullopt;
    type.remove_suffix(1);
  } else if (size_t slash = name.find('/'); slash != std::string_view::npos) {
    pkg = name.substr(0, slash);
    type = name.substr(slash + 1);
    if (type.substr(0, 4) == "msg/") type = type.substr(4);
  }
  if (pkg.empty() || type.empty()) return std::nullopt;
  for (char c : pkg)
    if (!is_name_char(c)) return std::nullopt;
  for (char c : type)
    if (!is_name_char(c)) return std::nullopt;
  return std::make_pair(std::string(pkg), std::string(type));
}

std::optional<MsgDefinition> parse_msg(std::string_view text, const std::string& package,
                                       const std::string& name, const std::string& file,
                                       MsgError* err) {
  MsgDefinition def;
  def.package = package;
  def.name = name;
  def.file = file;
  int number = 0;
  while (!text.empty()) {
    size_t nl = text.find('\n');
    std::string_view raw = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    ++number;
    std::string_view body = without_comment(raw);
    std::string_view trimmed = trim(body);
    if (trimmed.empty()) continue;
    Line l{trimmed, number, static_cast<int>(trimmed.data() - raw.data()) + 1};
    if (trimmed == "---") {
      *err = {file, number, l.column,
              "'---' separates a service's or an action's parts: a .msg file has one part"};
      return std::nullopt;
    }
    int column = l.column;
    std::string why = parse_line(l, package, &def, &column);
    if (!why.empty()) {
      *err = {file, number, column, why};
      return std::nullopt;
    }
  }
  return def;
}

}  // namespace arbc::ros2
