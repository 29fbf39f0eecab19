#include "compiler/codegen/lua_text.h"

#include <array>
#include <charconv>
#include <cmath>

#include "compiler/codegen/lua_prelude.h"
#include "core/quote.h"

namespace arbc::codegen {

namespace {

constexpr std::array<std::string_view, 22> kLuaKeywords = {
    "and",      "break",  "do",   "else", "elseif", "end",  "false", "for",
    "function", "goto",   "if",   "in",   "local",  "nil",  "not",   "or",
    "repeat",   "return", "then", "true", "until",  "while"};

bool is_plain_name(std::string_view s) {
  if (s.empty()) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(s[0])) return false;
  for (char c : s)
    if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
  return !is_lua_keyword(s);
}

}  // namespace

bool is_lua_keyword(std::string_view name) {
  for (std::string_view k : kLuaKeywords)
    if (k == name) return true;
  return false;
}

std::string lua_string(std::string_view text) { return quoted(text, QuoteStyle::Lua); }

std::string lua_float(double value) {
  if (std::isnan(value)) return "(0/0)";
  if (std::isinf(value)) return value > 0 ? "(1/0)" : "(-1/0)";
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  std::string out(buf, end);
  if (out.find_first_of(".eEn") == std::string::npos) out += ".0";
  return out;
}

std::string lua_local_name(std::string_view spec_name) {
  std::string out(spec_name);
  if (is_lua_keyword(spec_name) || is_reserved_lua_name(spec_name) ||
      (!spec_name.empty() && spec_name.back() == '_'))
    out += '_';
  return out;
}

std::string lua_field(std::string_view field) {
  if (is_plain_name(field)) return "." + std::string(field);
  return "[" + lua_string(field) + "]";
}

std::string lua_table_key(std::string_view field) {
  if (is_plain_name(field)) return std::string(field) + " = ";
  return "[" + lua_string(field) + "] = ";
}

std::string lua_comment_text(std::string_view text) {
  std::string out;
  for (char c : text) out += (c == '\n' || c == '\r') ? ' ' : c;
  return out;
}

}  // namespace arbc::codegen
