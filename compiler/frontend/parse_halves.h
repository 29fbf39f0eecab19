// A large spec is lexed, checked, parsed and built into an AST in two halves on two threads.
//
// Why: on a 10,000-rule spec the front end is nine tenths of `arbc check` and of `arbc build`'s
// compile phase, all on one thread (docs/benchmarks.md). Declarations are independent until
// semantic analysis: the grammar's declarations all end in `;` or `}` with nothing optional
// after, so where one ends is known without looking further, and the AST builder keeps no state
// from one declaration to the next (except "only one app", which the merge checks). The text is
// cut at the start of a line that starts a declaration; each half gets its own lexer, parser and
// DFA caches; the two ASTs are then concatenated kind by kind, which gives the same vectors in
// the same order as one parse.
//
// Whatever goes wrong (a lexical mistake, a syntax error, a cut that is not between two
// declarations, two `app` lines), the two-thread parse gives up and the caller parses the
// whole text on one thread, so diagnostics are exactly the one-thread parse's.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "compiler/frontend/parse.h"

namespace arbc::frontend {

// Where to cut `text`: the byte offset of the first line after its middle that starts with a
// declaration keyword (a guess, checked by parse_halves), or nullopt.
std::optional<size_t> find_split(std::string_view text);

// The AST and the AST builder's diagnostics for `text` (valid UTF-8, `code_points` decoded from
// it) parsed as [0, split) and [split, end) on two threads; nullopt if either half has a
// lexical, nesting or syntax error or the halves do not join (see above).
std::optional<ParseResult> parse_halves(std::string_view text, const std::u32string& code_points,
                                        const std::string& file, size_t split);

}  // namespace arbc::frontend
