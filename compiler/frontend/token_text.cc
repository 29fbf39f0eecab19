#include "compiler/frontend/token_text.h"

#include <antlr4-runtime.h>

namespace arbc::frontend {

TokenText::TokenText(std::string_view source) : source_(source) {
  bool ascii = true;
  for (char c : source)
    if (static_cast<unsigned char>(c) >= 0x80) ascii = false;
  if (ascii) return;
  offsets_.reserve(source.size() + 1);
  for (size_t i = 0; i < source.size(); ++i)
    if ((static_cast<unsigned char>(source[i]) & 0xC0) != 0x80)  // not a continuation byte
      offsets_.push_back(static_cast<uint32_t>(i));
  offsets_.push_back(static_cast<uint32_t>(source.size()));
}

std::string TokenText::text(const antlr4::Token* token) const {
  if (token->getType() == antlr4::Token::EOF) return {};
  size_t start = token->getStartIndex();
  size_t end = token->getStopIndex() + 1;  // code points, exclusive
  if (!offsets_.empty()) {
    start = offsets_[start];
    end = offsets_[end];
  }
  if (start > source_.size() || end > source_.size() || end < start) return token->getText();
  return std::string(source_.substr(start, end - start));
}

}  // namespace arbc::frontend
