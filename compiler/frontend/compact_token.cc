#include "compiler/frontend/compact_token.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include "compiler/frontend/thread_dfa.h"

namespace arbc::frontend {

namespace {

constexpr size_t kBlockBytes = 64u << 10;  // about 1,600 tokens a block

// `value` as a T, whose largest value is kept for "none" (INVALID_INDEX, EOF's type).
template <typename T>
T narrow(size_t value, const char* what) {
  if (value >= std::numeric_limits<T>::max())
    throw std::out_of_range(std::string("token ") + what +
                            " out of range: " + std::to_string(value));
  return static_cast<T>(value);
}

}  // namespace

static_assert(sizeof(CompactToken) == 40, "the point of CompactToken is its size");

void* TokenArena::allocate(size_t bytes) {
  bytes = (bytes + alignof(CompactToken) - 1) & ~(alignof(CompactToken) - 1);
  if (blocks_.empty() || used_ + bytes > kBlockBytes) {
    // for_overwrite: the block is left untouched until a token is constructed in it.
    blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(std::max(bytes, kBlockBytes)));
    used_ = 0;
  }
  void* at = blocks_.back().get() + used_;
  used_ += bytes;
  return at;
}

const std::string* TokenArena::text(const void* token) const {
  auto it = texts_.find(token);
  return it == texts_.end() ? nullptr : &it->second;
}

bool CompactToken::fits(size_t type, size_t channel, size_t start, size_t stop, size_t line,
                        size_t column) {
  return type < UINT16_MAX && channel < UINT8_MAX && start < UINT32_MAX && stop < UINT32_MAX &&
         line < UINT32_MAX && column < UINT32_MAX;
}

CompactToken::CompactToken(TokenArena& arena, size_t type, size_t start, size_t stop, size_t line,
                           size_t column)
    : arena_(&arena),
      start_(narrow<uint32_t>(start, "start")),
      stop_(narrow<uint32_t>(stop, "stop")),
      line_(narrow<uint32_t>(line, "line")),
      column_(narrow<uint32_t>(column, "column")),
      type_(narrow<uint16_t>(type, "type")) {}

std::string CompactToken::getText() const {
  if (has_text_) return *arena_->text(this);
  antlr4::CharStream* input = arena_->input();
  if (!input) return "";
  if (start_ >= input->size() || stop_ >= input->size()) return "<EOF>";
  return input->getText(antlr4::misc::Interval(size_t{start_}, size_t{stop_}));
}

std::string CompactToken::toString() const {
  // The shape of CommonToken::toString, for ANTLR's own diagnostics.
  return "[@" + std::to_string(static_cast<long long>(getTokenIndex())) + "," +
         std::to_string(start_) + ":" + std::to_string(stop_) + "='" + getText() + "',<" +
         std::to_string(type_) + ">," + std::to_string(line_) + ":" + std::to_string(column_) + "]";
}

void CompactToken::setText(const std::string& text) {
  arena_->set_text(this, text);
  has_text_ = true;
}

void CompactToken::setType(size_t type) { type_ = narrow<uint16_t>(type, "type"); }
void CompactToken::setLine(size_t line) { line_ = narrow<uint32_t>(line, "line"); }
void CompactToken::setCharPositionInLine(size_t column) {
  column_ = narrow<uint32_t>(column, "column");
}
void CompactToken::setChannel(size_t channel) { channel_ = narrow<uint8_t>(channel, "channel"); }
void CompactToken::setTokenIndex(size_t index) {
  index_ = index == INVALID_INDEX ? UINT32_MAX : narrow<uint32_t>(index, "index");
}

CompactTokenLexer::CompactTokenLexer(antlr4::CharStream* input)
    : arbc_grammar::ArbcLexer(input), arena_(this, input) {
  delete _interpreter;  // the generated constructor's, over the process-wide cache
  _interpreter = make_thread_lexer_simulator(this).release();  // deleted by ~ArbcLexer
}

antlr4::Token* CompactTokenLexer::emit() {
  size_t stop = getCharIndex() - 1;
  if (!_text.empty() || !CompactToken::fits(type, channel, tokenStartCharIndex, stop,
                                            tokenStartLine, tokenStartCharPositionInLine))
    return ArbcLexer::emit();
  auto* token = new (arena_) CompactToken(arena_, type, tokenStartCharIndex, stop, tokenStartLine,
                                          tokenStartCharPositionInLine);
  if (channel != antlr4::Token::DEFAULT_CHANNEL) token->setChannel(channel);
  ArbcLexer::emit(std::unique_ptr<antlr4::Token>(token));
  return token;
}

}  // namespace arbc::frontend
