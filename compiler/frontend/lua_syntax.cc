#include "compiler/frontend/lua_syntax.h"

#include <lua.hpp>
#include <string_view>

#include "core/check_ids.h"

namespace arbc::frontend {

LuaSyntaxChecker::LuaSyntaxChecker() : L_(luaL_newstate()) {}

LuaSyntaxChecker::~LuaSyntaxChecker() {
  if (L_) lua_close(L_);
}

bool LuaSyntaxChecker::check(const std::string& text, const std::string& chunk_name,
                             std::string* err) {
  if (!L_) {
    *err = "out of memory";
    return false;
  }
  // Compiles without running: a syntax check only.
  bool ok = luaL_loadbuffer(L_, text.data(), text.size(), ("@" + chunk_name).c_str()) == LUA_OK;
  if (!ok) *err = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "unknown error";
  lua_settop(L_, 0);
  return ok;
}

bool check_lua_syntax(const std::string& text, const std::string& chunk_name, std::string* err) {
  return LuaSyntaxChecker().check(text, chunk_name, err);
}

namespace {

// Line `line` (1-based) of text, without its newline.
std::string_view line_of(std::string_view text, int line) {
  size_t start = 0;
  for (int i = 1; i < line && start != std::string_view::npos; ++i) {
    start = text.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  if (start == std::string_view::npos || start > text.size()) return {};
  size_t end = text.find('\n', start);
  return text.substr(start, end == std::string_view::npos ? end : end - start);
}

// Columns count characters (UTF-8 continuation bytes add nothing), as everywhere else.
int column_of(std::string_view line, size_t byte) {
  int column = 1;
  for (size_t i = 0; i < byte && i < line.size(); ++i)
    column += (static_cast<unsigned char>(line[i]) & 0xC0) != 0x80;
  return column;
}

// Where the message "near 'TOKEN'" points on its line: the token's first occurrence (Lua names
// no column), or the line's end for "near <eof>". Sets the location's columns.
void locate_token(std::string_view message, std::string_view line, model::SourceLocation& loc) {
  loc.column = loc.end_column = 1;
  if (message.find("near <eof>") != std::string_view::npos) {
    loc.column = loc.end_column = column_of(line, line.size());
    return;
  }
  size_t near = message.rfind("near '");
  if (near == std::string_view::npos) return;
  std::string_view token = message.substr(near + 6);
  token = token.substr(0, token.rfind('\''));
  size_t at = token.empty() ? std::string_view::npos : line.find(token);
  if (at == std::string_view::npos) return;
  loc.column = column_of(line, at);
  loc.end_column = column_of(line, at + token.size());
}

}  // namespace

std::optional<Diagnostic> lua_syntax_diagnostic(const std::string& text, const std::string& path,
                                                const model::SourceLocation& used_at) {
  std::string error;
  if (check_lua_syntax(text, path, &error)) return std::nullopt;
  Diagnostic d;
  d.id = diag::Script.text();
  d.loc.file = path;
  // Lua's message is "PATH:LINE: what"; the location goes into the diagnostic's own fields.
  std::string_view what = error;
  if (what.substr(0, path.size() + 1) == path + ":") {
    std::string_view rest = what.substr(path.size() + 1);
    size_t colon = rest.find(": ");
    if (colon != std::string_view::npos && colon > 0 &&
        rest.substr(0, colon).find_first_not_of("0123456789") == std::string_view::npos) {
      d.loc.line = d.loc.end_line = std::stoi(std::string(rest.substr(0, colon)));
      what = rest.substr(colon + 2);
    }
  }
  if (d.loc.line > 0) locate_token(what, line_of(text, d.loc.line), d.loc);
  d.message = "the script does not compile as Lua 5.4: " + std::string(what);
  Diagnostic note;
  note.severity = Severity::Note;
  note.loc = used_at;
  note.message = "the script is used here";
  d.notes.push_back(std::move(note));
  return d;
}

}  // namespace arbc::frontend
