// Checks that Lua compiles: hand-written scripts (`script "file.lua"`) when a spec is checked, so
// a syntax error is an `arbc check` diagnostic in the script's file and line rather than a
// monitor failing at run time, and every monitor code generation writes.
#pragma once

#include <optional>
#include <string>

#include "core/diagnostic.h"

struct lua_State;

namespace arbc::frontend {

// True when `text` compiles as a Lua 5.4 chunk; otherwise false and Lua's message in `err`
// ("x.lua:3: ...").
bool check_lua_syntax(const std::string& text, const std::string& chunk_name, std::string* err);

// A `script` file whose text does not compile, as a diagnostic with id "script" located in
// `path` at the line (and, when Lua names the offending token, the column) Lua reports, with a
// note at `used_at`, the `script` statement. nullopt when the text compiles.
std::optional<Diagnostic> lua_syntax_diagnostic(const std::string& text, const std::string& path,
                                                const model::SourceLocation& used_at);

// The same check for many chunks, reusing one Lua state (code generation checks every monitor
// it writes; a fresh state per chunk would cost more than the compiling).
class LuaSyntaxChecker {
 public:
  LuaSyntaxChecker();
  ~LuaSyntaxChecker();
  LuaSyntaxChecker(const LuaSyntaxChecker&) = delete;
  LuaSyntaxChecker& operator=(const LuaSyntaxChecker&) = delete;
  bool check(const std::string& text, const std::string& chunk_name, std::string* err);

 private:
  lua_State* L_;
};

}  // namespace arbc::frontend
