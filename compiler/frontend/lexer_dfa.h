// The spec lexer's DFA cache, one per thread, read without a lock.
//
// Why: ANTLR 4.9 shares one DFA cache among all the lexers of a grammar and guards each edge
// lookup, one per character of input, with a reader's lock built from a mutex and a condition
// variable: about a tenth of `arbc check`'s instructions on a large spec (docs/benchmarks.md).
// A cache that no other thread reads needs no lock for reading; it is built exactly as the
// shared one is, on first use (in the command-line tool both start empty with the process; each
// language-server thread warms its own).
#pragma once

#include <antlr4-runtime.h>

#include <memory>

namespace arbc::frontend {

// A simulator for `lexer` over the calling thread's cache for `lexer`'s grammar. The lexer must
// be used on this thread only, and there must be one lexer grammar in the process (arbc's).
std::unique_ptr<antlr4::atn::LexerATNSimulator> make_thread_lexer_simulator(antlr4::Lexer* lexer);

}  // namespace arbc::frontend
