#include "core/spec_identifier.h"

#include <algorithm>
#include <cctype>

namespace arbc {
namespace {

constexpr std::string_view kKeywords[] = {
    "accept",   "after",    "and",      "app",       "arbitrate", "assert", "assume",    "at",
    "by",       "complete", "connect",  "const",     "delivers",  "drops",  "else",      "emit",
    "event",    "events",   "every",    "exclusive", "expect",    "false",  "for",       "from",
    "given",    "hold",     "if",       "in",        "invariant", "let",    "lifetime",  "module",
    "never",    "not",      "nothing",  "on",        "only",      "or",     "otherwise", "out",
    "priority", "receives", "resource", "script",    "set",       "stable", "stops",     "test",
    "tests",    "then",     "throttle", "true",      "two",       "type",   "unset",     "until",
    "use",      "var",      "when",     "while",     "within",
};

}  // namespace

std::span<const std::string_view> spec_keywords() { return kKeywords; }

bool is_spec_keyword(std::string_view word) {
  return std::binary_search(std::begin(kKeywords), std::end(kKeywords), word);
}

std::string spec_identifier(std::string_view text) {
  std::string out;
  for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  while (!out.empty() && out.front() == '_') out.erase(out.begin());
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "p_" + out;
  if (is_spec_keyword(out)) out += "_";
  return out;
}

}  // namespace arbc
