// String literals for the languages arbc writes (JSON, Lua, Graphviz DOT): the one escaping
// routine of the project. HTML and Markdown text are not literals; report/html_text.h and
// compiler/docs/markdown_docs.h escape those.
#pragma once

#include <string>
#include <string_view>

namespace arbc {

enum class QuoteStyle {
  Json,  // \" \\ \n \r \t; other control bytes as \u00XX; other bytes as they are (UTF-8 passes)
  Lua,   // \" \\ \n \r \t; other control bytes and bytes from 0x7f as \ddd: the text stays ASCII
  Dot,   // \" and \\ only: Graphviz takes every other byte as it is
};

// Appends `s` in double quotes, escaped for `style`.
void append_quoted(std::string& out, std::string_view s, QuoteStyle style);

// `s` in double quotes, escaped for `style`.
std::string quoted(std::string_view s, QuoteStyle style);

}  // namespace arbc
