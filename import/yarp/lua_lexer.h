// Tokens of Lua 5.4 source (the lexical rules of the Lua 5.4 manual, section 3.1), for
// lua_parser.h. Strings are decoded (escapes, long brackets); comments are skipped.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbc::yarp {

struct LuaToken {
  enum class Kind { Name, Keyword, Number, String, Symbol, End };
  Kind kind = Kind::End;
  std::string text;  // Name, Keyword, Symbol: as written; String: the decoded value
  double number = 0;
  int line = 0;
};

// The whole source as tokens, ending with one End token. On a lexical error returns nullopt
// and sets *err to "LINE: what is wrong".
std::optional<std::vector<LuaToken>> lua_tokens(std::string_view source, std::string* err);

}  // namespace arbc::yarp
