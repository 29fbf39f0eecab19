// What tools beside the compiler need to know about the grammar without linking the generated
// parser themselves: its keywords (for completion) and a way to drop the parser's prediction
// cache (a long-lived process such as `arbc lsp`: docs/reliability.md, the spec front end).
#pragma once

#include <string>
#include <vector>

namespace arbc::frontend {

// Every keyword of the spec language (the grammar's alphabetic literals), sorted.
std::vector<std::string> grammar_keywords();

// Drops the lexer's and parser's process-wide prediction (DFA) caches, which grow with the
// variety of text parsed. Not thread-safe: no parse may run in any thread meanwhile.
void reset_parser_cache();

}  // namespace arbc::frontend
