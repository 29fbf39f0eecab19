#include "compiler/frontend/text_stream.h"

#include <algorithm>

namespace arbc::frontend {

// ANTLR's input stream decodes UTF-8 with std::wstring_convert, which is slow on large specs.
// The text is already validated, so it is decoded directly.
std::u32string decode_utf8(std::string_view utf8) {
  std::u32string out;
  out.reserve(utf8.size());
  for (size_t i = 0; i < utf8.size();) {
    unsigned char b = static_cast<unsigned char>(utf8[i]);
    size_t len = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
    char32_t code = len == 1 ? b : len == 2 ? (b & 0x1F) : len == 3 ? (b & 0x0F) : (b & 0x07);
    for (size_t k = 1; k < len && i + k < utf8.size(); ++k)
      code = (code << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
    out.push_back(code);
    i += len;
  }
  return out;
}

void TextStream::consume() {
  if (p_ >= end_) throw antlr4::IllegalStateException("cannot consume EOF");
  ++p_;
}

size_t TextStream::LA(ssize_t i) {
  if (i == 0) return 0;  // undefined, as in ANTLRInputStream
  ssize_t at = static_cast<ssize_t>(p_) + (i < 0 ? i : i - 1);
  if (at < 0 || at >= static_cast<ssize_t>(end_)) return antlr4::IntStream::EOF;
  return text_[static_cast<size_t>(at)];
}

void TextStream::seek(size_t index) { p_ = std::min(index, end_); }

std::string TextStream::getText(const antlr4::misc::Interval& interval) {
  if (interval.a < 0 || interval.b < 0 || static_cast<size_t>(interval.a) >= end_) return "";
  size_t start = static_cast<size_t>(interval.a);
  size_t stop = std::min(static_cast<size_t>(interval.b) + 1, end_);  // one past the last
  if (stop <= start) return "";
  return antlrcpp::utf32_to_utf8(text_.substr(start, stop - start));
}

std::string TextStream::toString() const { return antlrcpp::utf32_to_utf8(text_.substr(0, end_)); }

}  // namespace arbc::frontend
