// The spec's text as ANTLR's lexer reads it: code points, decoded from UTF-8 once and shared by
// every lexer that reads part of it.
//
// Why: a large spec is lexed in two parts on two threads (parse_halves.h), each lexer with a
// stream of its own over one shared buffer. ANTLR's own ANTLRInputStream owns its buffer, so two
// of them would decode the text twice; and the second part's tokens must carry their indices in
// the whole text, which a stream over a copy of the second part alone would not give.
#pragma once

#include <antlr4-runtime.h>

#include <string>
#include <string_view>

namespace arbc::frontend {

// The code points of `utf8`, which must be valid UTF-8 (find_invalid_utf8).
std::u32string decode_utf8(std::string_view utf8);

// Reads code points [0, end) of `text`, starting at `begin`; past `end` it reads EOF, so a lexer
// over it stops at `end` as at the end of the text. Behaves as ANTLRInputStream otherwise.
class TextStream : public antlr4::CharStream {
 public:
  // `text` must outlive the stream.
  TextStream(const std::u32string& text, size_t begin, size_t end)
      : text_(text), end_(end), p_(begin) {}

  void consume() override;
  size_t LA(ssize_t i) override;
  ssize_t mark() override { return -1; }
  void release(ssize_t) override {}
  size_t index() override { return p_; }
  void seek(size_t index) override;
  size_t size() override { return end_; }
  std::string getSourceName() const override { return antlr4::IntStream::UNKNOWN_SOURCE_NAME; }
  std::string getText(const antlr4::misc::Interval& interval) override;
  std::string toString() const override;

 private:
  const std::u32string& text_;
  size_t end_;
  size_t p_;
};

}  // namespace arbc::frontend
