#include "compiler/frontend/lexed_text.h"

namespace arbc::frontend {

LexedText::LexedText(const std::u32string& text, size_t begin, size_t end, size_t line,
                     size_t bytes)
    : input(text, begin, end),
      lexer(&input),
      // At most one token per byte, plus EOF; specs average one per four to five bytes.
      stream(&lexer, bytes / 2 + 16) {
  lexer.removeErrorListeners();  // ERROR_CHAR catches everything the lexer cannot match
  lexer.setLine(line);
  stream.fill();
  tokens.reserve(stream.size());
  // stream.get(i), not getTokens(): that returns a fresh copy of the whole buffer.
  for (size_t i = 0; i < stream.size(); ++i) {
    antlr4::Token* t = stream.get(i);
    if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) tokens.push_back(t);
  }
}

}  // namespace arbc::frontend
