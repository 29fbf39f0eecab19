#include "import/yarp/lua_lexer.h"

#include <array>
#include <cctype>
#include <cstdlib>

namespace arbc::yarp {
namespace {

constexpr std::array<std::string_view, 22> kKeywords = {
    "and",      "break",  "do",   "else", "elseif", "end",  "false", "for",
    "function", "goto",   "if",   "in",   "local",  "nil",  "not",   "or",
    "repeat",   "return", "then", "true", "until",  "while"};

// Longest first, so that `...` wins over `..` and `..` over `.`.
constexpr std::array<std::string_view, 33> kSymbols = {
    "...", "==", "~=", "<=", ">=", "//", "::", "<<", ">>", "..", "+", "-", "*", "/", "%", "^", "#",
    "&",   "~",  "|",  "<",  ">",  "=",  "(",  ")",  "{",  "}",  "[", "]", ";", ":", ",", "."};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

void append_utf8(std::string& out, unsigned long cp) {
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

class Lexer {
 public:
  explicit Lexer(std::string_view s) : s_(s) {}

  std::optional<std::vector<LuaToken>> run(std::string* err) {
    std::vector<LuaToken> out;
    while (true) {
      if (!skip_space_and_comments()) return fail(err);
      LuaToken t;
      t.line = line_;
      if (pos_ >= s_.size()) {
        t.kind = LuaToken::Kind::End;
        out.push_back(t);
        return out;
      }
      if (!next(t)) return fail(err);
      out.push_back(std::move(t));
    }
  }

 private:
  std::optional<std::vector<LuaToken>> fail(std::string* err) {
    if (err) *err = std::to_string(line_) + ": " + error_;
    return std::nullopt;
  }
  char at(size_t i) const { return i < s_.size() ? s_[i] : '\0'; }
  void advance() {
    if (s_[pos_] == '\n') ++line_;
    ++pos_;
  }

  // The level of a long bracket `[==[` at pos_ (number of `=`), or -1.
  int long_bracket_level() const {
    if (at(pos_) != '[') return -1;
    size_t i = pos_ + 1;
    while (at(i) == '=') ++i;
    return at(i) == '[' ? static_cast<int>(i - pos_ - 1) : -1;
  }

  bool read_long(int level, std::string* out) {
    pos_ += static_cast<size_t>(level) + 2;
    if (at(pos_) == '\r' || at(pos_) == '\n') advance();  // a first newline is skipped
    std::string close = "]" + std::string(static_cast<size_t>(level), '=') + "]";
    while (pos_ < s_.size()) {
      if (s_.compare(pos_, close.size(), close) == 0) {
        pos_ += close.size();
        return true;
      }
      if (out) *out += s_[pos_];
      advance();
    }
    error_ = "unfinished long string or comment";
    return false;
  }

  bool skip_space_and_comments() {
    if (pos_ == 0 && s_.substr(0, 1) == "#") {  // a first line starting with # (a shebang)
      while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    }
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else if (c == '-' && at(pos_ + 1) == '-') {
        pos_ += 2;
        int level = long_bracket_level();
        if (level >= 0) {
          if (!read_long(level, nullptr)) return false;
        } else {
          while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
        }
      } else {
        return true;
      }
    }
    return true;
  }

  bool next(LuaToken& t) {
    char c = s_[pos_];
    if (is_name_start(c)) {
      size_t start = pos_;
      while (is_name_char(at(pos_))) ++pos_;
      t.text = std::string(s_.substr(start, pos_ - start));
      t.kind = LuaToken::Kind::Name;
      for (std::string_view k : kKeywords) {
        if (t.text == k) t.kind = LuaToken::Kind::Keyword;
      }
      return true;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && std::isdigit(static_cast<unsigned char>(at(pos_ + 1))))) {
      return number(t);
    }
    if (c == '"' || c == '\'') return short_string(t);
    int level = long_bracket_level();
    if (level >= 0) {
      t.kind = LuaToken::Kind::String;
      return read_long(level, &t.text);
    }
    for (std::string_view sym : kSymbols) {
      if (s_.compare(pos_, sym.size(), sym) == 0) {
        t.kind = LuaToken::Kind::Symbol;
        t.text = std::string(sym);
        pos_ += sym.size();
        return true;
      }
    }
    error_ = std::string("unexpected character '") + c + "'";
    return false;
  }

  bool number(LuaToken& t) {
    size_t start = pos_;
    bool hex = at(pos_) == '0' && (at(pos_ + 1) == 'x' || at(pos_ + 1) == 'X');
    if (hex) pos_ += 2;
    while (true) {
      char c = at(pos_);
      char e1 = hex ? 'p' : 'e', e2 = hex ? 'P' : 'E';
      if ((c == e1 || c == e2) && (at(pos_ + 1) == '+' || at(pos_ + 1) == '-')) {
        pos_ += 2;
      } else if (std::isxdigit(static_cast<unsigned char>(c)) || c == '.' || c == e1 || c == e2) {
        ++pos_;
      } else {
        break;
      }
    }
    std::string text(s_.substr(start, pos_ - start));
    char* end = nullptr;
    t.number = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || is_name_char(at(pos_))) {
      error_ = "malformed number near '" + text + "'";
      return false;
    }
    t.kind = LuaToken::Kind::Number;
    t.text = text;
    return true;
  }

  bool escape(std::string& out) {
    char c = at(pos_);
    static constexpr std::string_view from = "abfnrtv\\\"'", to = "\a\b\f\n\r\t\v\\\"'";
    if (size_t k = from.find(c); k != std::string_view::npos && c != '\0') {
      out += to[k];
      ++pos_;
    } else if (c == '\n' || c == '\r') {
      out += '\n';
      advance();
    } else if (c == 'x') {
      std::string hex(s_.substr(pos_ + 1, 2));
      if (hex.size() != 2 || !std::isxdigit(static_cast<unsigned char>(hex[0])) ||
          !std::isxdigit(static_cast<unsigned char>(hex[1]))) {
        error_ = "hexadecimal digit expected in \\x escape";
        return false;
      }
      out += static_cast<char>(std::strtol(hex.c_str(), nullptr, 16));
      pos_ += 3;
    } else if (c == 'z') {
      ++pos_;
      while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) advance();
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      int v = 0;
      for (int i = 0; i < 3 && std::isdigit(static_cast<unsigned char>(at(pos_))); ++i) {
        v = v * 10 + (s_[pos_++] - '0');
      }
      if (v > 255) {
        error_ = "decimal escape too large";
        return false;
      }
      out += static_cast<char>(v);
    } else if (c == 'u' && at(pos_ + 1) == '{') {
      size_t close = s_.find('}', pos_);
      if (close == std::string_view::npos) {
        error_ = "missing '}' in \\u{XXXX}";
        return false;
      }
      append_utf8(out, std::strtoul(std::string(s_.substr(pos_ + 2, close - pos_ - 2)).c_str(),
                                    nullptr, 16));
      pos_ = close + 1;
    } else {
      error_ = "invalid escape sequence";
      return false;
    }
    return true;
  }

  bool short_string(LuaToken& t) {
    char quote = s_[pos_++];
    t.kind = LuaToken::Kind::String;
    while (true) {
      char c = at(pos_);
      if (pos_ >= s_.size() || c == '\n') {
        error_ = "unfinished string";
        return false;
      }
      ++pos_;
      if (c == quote) return true;
      if (c != '\\') {
        t.text += c;
      } else if (!escape(t.text)) {
        return false;
      }
    }
  }

  std::string_view s_;
  size_t pos_ = 0;
  int line_ = 1;
  std::string error_;
};

}  // namespace

std::optional<std::vector<LuaToken>> lua_tokens(std::string_view source, std::string* err) {
  return Lexer(source).run(err);
}

}  // namespace arbc::yarp
