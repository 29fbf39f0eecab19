// The spec lexer's and parser's DFA caches, one per thread, read without a lock.
//
// Why: ANTLR 4.9 shares one DFA cache among all the lexers (and one among all the parsers) of a
// grammar and guards each edge lookup with a reader's lock built from a mutex and a condition
// variable. The lexer looks up an edge for every character of input and the parser one for
// every token it predicts over: together about a seventh of `arbc check`'s instructions on a
// large spec (docs/benchmarks.md). A cache that no other thread reads needs no lock for
// reading; it is built exactly as the shared one is, on first use (in the command-line tool
// both start empty with the process; each language-server thread warms its own).
#pragma once

#include <antlr4-runtime.h>

#include <memory>

namespace arbc::frontend {

// A simulator for `lexer` over the calling thread's cache for `lexer`'s grammar. The lexer must
// then be used on this thread only.
std::unique_ptr<antlr4::atn::LexerATNSimulator> make_thread_lexer_simulator(antlr4::Lexer* lexer);

// The same for a parser.
std::unique_ptr<antlr4::atn::ParserATNSimulator> make_thread_parser_simulator(
    antlr4::Parser* parser);

}  // namespace arbc::frontend
