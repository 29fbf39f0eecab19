// A token's text, cut straight from the UTF-8 source. ANTLR's Token::getText() converts from
// its UTF-32 buffer on every call, which dominated the AST builder's time on large specs.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace antlr4 {
class Token;
}

namespace arbc::frontend {

class TokenText {
 public:
  // `source` must outlive this object and be the text the lexer read.
  explicit TokenText(std::string_view source);
  // The token's text (EOF has none).
  std::string text(const antlr4::Token* token) const;

 private:
  std::string_view source_;
  // Byte offset of each code point; empty when the source is ASCII (offsets are indices).
  std::vector<uint32_t> offsets_;
};

}  // namespace arbc::frontend
