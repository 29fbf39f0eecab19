#include "compiler/codegen/lua_prelude.h"

#include <array>
#include <string_view>
#include <vector>

#include "core/builtins.h"

namespace arbc::embedded {
// lua_prelude.lua, embedded at build time (arbc_embed_text), where luac -p and the gates see it.
extern const std::string_view kLuaPrelude;
}  // namespace arbc::embedded

namespace arbc::codegen {

namespace {

struct Helper {
  std::string name;
  std::string needs;   // the helper this one calls, if any (else empty)
  std::string source;  // copied into a monitor as it is
};

constexpr std::string_view kMarker = "--@ helper ";

// The helpers of lua_prelude.lua in its order (a helper after those it calls), read once.
const std::vector<Helper>& helpers() {
  static const std::vector<Helper> all = [] {
    std::vector<Helper> out;
    std::string_view text = embedded::kLuaPrelude;
    while (!text.empty()) {
      size_t end = text.find('\n');
      std::string_view line = text.substr(0, end == std::string_view::npos ? text.size() : end + 1);
      text.remove_prefix(line.size());
      if (line.substr(0, kMarker.size()) == kMarker) {
        std::string_view words = line.substr(kMarker.size());
        while (!words.empty() && (words.back() == '\n' || words.back() == '\r'))
          words.remove_suffix(1);
        size_t space = words.find(" needs ");
        out.push_back({std::string(words.substr(0, space)),
                       space == std::string_view::npos ? "" : std::string(words.substr(space + 7)),
                       ""});
      } else if (!out.empty()) {
        out.back().source += line;  // the file's opening comment belongs to no helper
      }
    }
    return out;
  }();
  return all;
}

const Helper* find_helper(std::string_view name) {
  for (const Helper& h : helpers())
    if (h.name == name) return &h;
  return nullptr;
}

void add_with_needs(std::string_view name, std::set<std::string>& closure) {
  const Helper* h = find_helper(name);
  if (!h || !closure.insert(std::string(name)).second) return;
  if (!h->needs.empty()) add_with_needs(h->needs, closure);
}

// Lua globals the generated code or the helpers call; a spec name must not shadow them.
constexpr std::array<std::string_view, 21> kLuaGlobals = {
    "PortMonitor", "math",   "string",   "table",        "error",    "pcall",    "ipairs",
    "pairs",       "select", "type",     "setmetatable", "tostring", "rawequal", "next",
    "print",       "unpack", "tonumber", "assert",       "utf8",     "_ENV",     "_G"};

}  // namespace

bool is_builtin(std::string_view name) {
  for (const BuiltinInfo& b : kBuiltins)
    if (b.lua_helper == name) return true;
  return false;
}

bool is_reserved_lua_name(std::string_view name) {
  if (name.substr(0, 5) == "arbc_") return true;
  if (is_builtin(name)) return true;
  for (std::string_view g : kLuaGlobals)
    if (g == name) return true;
  return false;
}

std::set<std::string> helper_closure(const std::set<std::string>& used) {
  std::set<std::string> closure;
  for (const std::string& name : used) add_with_needs(name, closure);
  return closure;
}

std::string lua_prelude(const std::set<std::string>& used) {
  std::set<std::string> closure = helper_closure(used);
  std::string out;
  for (const Helper& h : helpers())
    if (closure.count(h.name)) out += h.source;
  return out;
}

}  // namespace arbc::codegen
