// Checks on the token stream before the parser runs: lexical mistakes the grammar only
// catches so that we can name them (a number with a bad unit, an unterminated string or
// comment, a stray character), and the nesting bound that keeps the generated recursive
// descent parser from exhausting the stack on hostile input.
#pragma once

#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace antlr4 {
class Token;
namespace dfa {
class Vocabulary;
}
}  // namespace antlr4

namespace arbc::frontend {

// Brackets ( [ { and prefix operators (`not`, unary `-`, lambda arrows) nest at most this deep.
// docs/language.md documents the limit; the AST builder applies the same bound to operator chains.
inline constexpr int kMaxNesting = 100;

// Appends a diagnostic for each lexical mistake among `tokens` (default channel, EOF last).
void check_lexical(const std::vector<antlr4::Token*>& tokens, const std::string& file,
                   std::vector<Diagnostic>& out);

// Appends one diagnostic if brackets or prefix operators nest deeper than kMaxNesting.
// Returns false in that case (the parser must not run).
bool check_nesting(const std::vector<antlr4::Token*>& tokens,
                   const antlr4::dfa::Vocabulary& vocabulary, const std::string& file,
                   std::vector<Diagnostic>& out);

// The location of one token.
model::SourceLocation token_location(const antlr4::Token* token, const model::FileName& file);

}  // namespace arbc::frontend
