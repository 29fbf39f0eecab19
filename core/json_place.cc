#include "core/json_place.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>

namespace arbc {

namespace {

constexpr size_t npos = std::string_view::npos;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

size_t skip_space(std::string_view t, size_t i) {
  while (i < t.size() && is_space(t[i])) ++i;
  return i;
}

// i at an opening quote: the offset just past the closing one, or npos.
size_t skip_string(std::string_view t, size_t i) {
  for (++i; i < t.size(); ++i) {
    if (t[i] == '\\') {
      ++i;
    } else if (t[i] == '"') {
      return i + 1;
    }
  }
  return npos;
}

// i at a value: the offset just past it, or npos. Containers are walked with a depth counter,
// so that no nesting the library accepted can exhaust the stack here.
size_t skip_value(std::string_view t, size_t i) {
  if (i >= t.size()) return npos;
  if (t[i] == '"') return skip_string(t, i);
  if (t[i] == '{' || t[i] == '[') {
    size_t depth = 0;
    while (i < t.size()) {
      char c = t[i];
      if (c == '"') {
        i = skip_string(t, i);
        if (i == npos) return npos;
        continue;
      }
      if (c == '{' || c == '[') {
        ++depth;
      } else if ((c == '}' || c == ']') && --depth == 0) {
        return i + 1;
      }
      ++i;
    }
    return npos;
  }
  size_t start = i;  // a number, true, false or null
  while (i < t.size() && !is_space(t[i]) && t[i] != ',' && t[i] != ']' && t[i] != '}') ++i;
  return i == start ? npos : i;
}

void append_utf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// The four hex digits at i, or nothing.
std::optional<uint32_t> hex4(std::string_view t, size_t i) {
  uint32_t value = 0;
  if (i + 4 > t.size()) return std::nullopt;
  auto [end, ec] = std::from_chars(t.data() + i, t.data() + i + 4, value, 16);
  if (ec != std::errc() || end != t.data() + i + 4) return std::nullopt;
  return value;
}

// i at an opening quote: the string's content decoded as the library decodes keys, with *end
// just past the closing quote; nothing when it is not a well-formed string.
std::optional<std::string> read_string(std::string_view t, size_t i, size_t* end) {
  std::string out;
  for (++i; i < t.size(); ++i) {
    char c = t[i];
    if (c == '"') {
      *end = i + 1;
      return out;
    }
    if (c != '\\') {
      out += c;
      continue;
    }
    if (++i >= t.size()) return std::nullopt;
    switch (t[i]) {
      case 'b':
        out += '\b';
        break;
      case 'f':
        out += '\f';
        break;
      case 'n':
        out += '\n';
        break;
      case 'r':
        out += '\r';
        break;
      case 't':
        out += '\t';
        break;
      case 'u': {
        std::optional<uint32_t> cp = hex4(t, i + 1);
        if (!cp) return std::nullopt;
        i += 4;
        // A surrogate pair is one character, written as two escapes.
        if (*cp >= 0xD800 && *cp < 0xDC00 && i + 2 < t.size() && t[i + 1] == '\\' &&
            t[i + 2] == 'u') {
          std::optional<uint32_t> low = hex4(t, i + 3);
          if (low && *low >= 0xDC00 && *low < 0xE000) {
            *cp = 0x10000 + ((*cp - 0xD800) << 10) + (*low - 0xDC00);
            i += 6;
          }
        }
        append_utf8(out, *cp);
        break;
      }
      default:  // \" \\ \/
        out += t[i];
    }
  }
  return std::nullopt;
}

// i at '{': the last member named `key`, its key's offsets and its value's start.
bool find_member(std::string_view t, size_t i, const std::string& key, size_t* key_begin,
                 size_t* key_end, size_t* value) {
  bool found = false;
  i = skip_space(t, i + 1);
  while (i < t.size() && t[i] == '"') {
    size_t name_end = 0;
    std::optional<std::string> name = read_string(t, i, &name_end);
    if (!name) return found;
    size_t colon = skip_space(t, name_end);
    if (colon >= t.size() || t[colon] != ':') return found;
    size_t v = skip_space(t, colon + 1);
    if (*name == key) {
      found = true;
      *key_begin = i;
      *key_end = name_end;
      *value = v;
    }
    size_t after = skip_value(t, v);
    if (after == npos) return found;
    i = skip_space(t, after);
    if (i >= t.size() || t[i] != ',') break;
    i = skip_space(t, i + 1);
  }
  return found;
}

// i at '[': the start of the element whose index `index` writes in decimal.
bool find_element(std::string_view t, size_t i, const std::string& index, size_t* value) {
  size_t n = 0;
  auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), n);
  if (index.empty() || ec != std::errc() || end != index.data() + index.size()) return false;
  i = skip_space(t, i + 1);
  if (i < t.size() && t[i] == ']') return false;
  for (size_t k = 0; i < t.size(); ++k) {
    if (k == n) {
      *value = i;
      return true;
    }
    size_t after = skip_value(t, i);
    if (after == npos) return false;
    i = skip_space(t, after);
    if (i >= t.size() || t[i] != ',') return false;
    i = skip_space(t, i + 1);
  }
  return false;
}

TextSpan span(std::string_view t, size_t begin, size_t end) {
  return {text_position(t, begin), text_position(t, end)};
}

}  // namespace

std::optional<TextSpan> json_place(std::string_view text, const std::vector<std::string>& path,
                                   JsonPart part) {
  size_t i = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;  // a byte order mark, as the library
  i = skip_space(text, i);
  size_t key_begin = npos, key_end = npos;
  for (const std::string& step : path) {
    if (i >= text.size()) return std::nullopt;
    key_begin = key_end = npos;
    bool found = text[i] == '{'   ? find_member(text, i, step, &key_begin, &key_end, &i)
                 : text[i] == '[' ? find_element(text, i, step, &i)
                                  : false;
    if (!found) return std::nullopt;
  }
  if (part == JsonPart::Key) {
    if (key_begin == npos) return std::nullopt;
    return span(text, key_begin, key_end);
  }
  size_t end = skip_value(text, i);
  if (end == npos) return std::nullopt;
  return span(text, i, end);
}

std::optional<JsonRepeatedKey> json_repeated_key(std::string_view text) {
  // In JSON the library accepted, a string right after an object's '{' or after a ',' at the
  // object's own level is a key; any other string is a value. One frame per open container,
  // on a vector rather than the call stack.
  struct Frame {
    bool object = false;
    bool want_key = false;
    std::map<std::string, size_t> keys;  // decoded key -> its offset
  };
  std::vector<Frame> open;
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '{' || c == '[') {
      open.push_back({c == '{', c == '{', {}});
      ++i;
    } else if (c == '}' || c == ']') {
      if (!open.empty()) open.pop_back();
      ++i;
    } else if (c == ',') {
      if (!open.empty() && open.back().object) open.back().want_key = true;
      ++i;
    } else if (c == '"') {
      size_t end = npos;
      if (open.empty() || !open.back().want_key) {
        end = skip_string(text, i);
      } else {
        std::optional<std::string> key = read_string(text, i, &end);
        if (!key) return std::nullopt;
        Frame& f = open.back();
        f.want_key = false;
        auto [seen, fresh] = f.keys.emplace(*key, i);
        if (!fresh) {
          size_t first_end = skip_string(text, seen->second);
          return JsonRepeatedKey{*key, span(text, seen->second, first_end), span(text, i, end)};
        }
      }
      if (end == npos) return std::nullopt;
      i = end;
    } else {
      ++i;
    }
  }
  return std::nullopt;
}

std::optional<size_t> json_number_overflow(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '"') {
      i = skip_string(text, i);
      if (i == npos) return std::nullopt;
    } else if (c == '-' || is_digit(c)) {
      size_t start = i;
      while (i < text.size() && (is_digit(text[i]) ||
                                 std::string_view("+-.eE").find(text[i]) != std::string_view::npos))
        ++i;
      std::string literal(text.substr(start, i - start));
      if (std::isinf(std::strtod(literal.c_str(), nullptr))) return start;
    } else {
      ++i;
    }
  }
  return std::nullopt;
}

}  // namespace arbc
