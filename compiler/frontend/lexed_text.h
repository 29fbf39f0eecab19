// A range of the spec's text, lexed: the lexer, its token stream (filled) and the tokens on the
// default channel that the checks and the parser see.
#pragma once

#include <antlr4-runtime.h>

#include <string>
#include <vector>

#include "compiler/frontend/compact_token.h"
#include "compiler/frontend/text_stream.h"

namespace arbc::frontend {

// A token stream whose buffer is reserved for `expected` tokens up front. Growing it by doubling
// touches fresh memory at every step, and fresh memory costs a page fault (docs/benchmarks.md);
// a reservation only touches what the lexer fills.
class ReservedTokenStream : public antlr4::CommonTokenStream {
 public:
  ReservedTokenStream(antlr4::TokenSource* source, size_t expected)
      : antlr4::CommonTokenStream(source) {
    _tokens.reserve(expected);
  }
};

// Lexes code points [begin, end) of `text` on the calling thread (the lexer's DFA cache is the
// thread's own): tokens carry their indices in the whole text, and lines count from `line`, the
// line `begin` is on (`begin` starts a line). Not movable: the parts point at each other.
class LexedText {
 public:
  // `text` must outlive this object; `bytes` is the range's length in UTF-8, to size buffers.
  LexedText(const std::u32string& text, size_t begin, size_t end, size_t line, size_t bytes);
  LexedText(const LexedText&) = delete;
  LexedText& operator=(const LexedText&) = delete;

  TextStream input;
  CompactTokenLexer lexer;
  ReservedTokenStream stream;
  std::vector<antlr4::Token*> tokens;  // the default channel's, EOF last
};

}  // namespace arbc::frontend
