// The parser's state in the user's words, for syntax_errors.cc: what was being written (by
// grammar rule), how a token is named, which tokens the parser would have taken, and the
// messages of a few mistakes that need no more than that.
#pragma once

#include <antlr4-runtime.h>

#include <set>
#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace arbc::frontend {

// What the user was writing when the parser stopped, by grammar rule ("the rule"); rules not
// listed (expressions, port references...) defer to the enclosing rule; "the spec" at the top.
const char* describe_rule(size_t rule);
std::string describe_context(antlr4::ParserRuleContext* ctx);

// The innermost context of grammar rule `rule` around `ctx`, or null.
antlr4::ParserRuleContext* enclosing(antlr4::ParserRuleContext* ctx, size_t rule);
inline bool in_rule(antlr4::ParserRuleContext* ctx, size_t rule) { return enclosing(ctx, rule); }

// The words that start a declaration, and those that start a statement.
extern const std::set<std::string> kDeclKeywords;
extern const std::vector<std::string> kStatementKeywords;

// A token type as the user would name it ("a name", "'when'"); the text of a token found
// ("'x'", "the end of the file"); whether a token is a keyword.
std::string token_name(const antlr4::dfa::Vocabulary& vocabulary, size_t type);
std::string found_text(const antlr4::Token* token);
bool is_keyword(const antlr4::dfa::Vocabulary& vocabulary, const antlr4::Token* token);

// The tokens the parser would have accepted where it stopped.
struct Expected {
  std::set<std::string> literals;   // literal tokens, unquoted
  std::set<size_t> kinds;           // token types
  std::vector<std::string> wanted;  // as the user names them, minus operators that would only
                                    // continue an expression
  bool has(const char* literal) const { return literals.count(literal) > 0; }
};
Expected expected_tokens(antlr4::Parser* parser);

// A test step that starts well ('at' or 'expect', the token `start`) but fits none of its
// forms: the message and a note with the forms it may take.
void describe_test_step(const antlr4::Token* start, const antlr4::Token* offending,
                        const std::string& found, Diagnostic& d);

// ": 1ms" for the number "1e-3" and the unit "s": the duration they mean, as the language
// writes it; " (in ms, s or min)" when none can be written (below the microsecond).
std::string exponent_free_duration(const std::string& number, const std::string& unit);

}  // namespace arbc::frontend
