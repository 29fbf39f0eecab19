// Tokens for the spec lexer that cost 40 bytes each in a shared arena instead of a 112-byte
// CommonToken (plus malloc's header) per token.
//
// Why: `arbc check` keeps every token of the spec until the parse ends (the lexical and nesting
// checks read them all first). On a 10,000-rule spec that was about 275,000 tokens, 35 MB of
// fresh heap, and on these virtual machines fresh memory is paid for by a page fault that
// clears it: a third of the front end's time (docs/benchmarks.md). The arbc lexer never sets a
// token's text by an action, so a token's text is always its range of the input, and the
// fields that hold it can be dropped.
#pragma once

#include <ArbcLexer.h>
#include <antlr4-runtime.h>

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace arbc::frontend {

// Owns the memory of every CompactToken made with it. Must outlive the tokens' owner (the token
// stream), whose destruction of a token only runs its destructor.
class TokenArena {
 public:
  TokenArena(antlr4::TokenSource* source, antlr4::CharStream* input)
      : source_(source), input_(input) {}
  TokenArena(const TokenArena&) = delete;
  TokenArena& operator=(const TokenArena&) = delete;

  void* allocate(size_t bytes);
  antlr4::TokenSource* source() const { return source_; }
  antlr4::CharStream* input() const { return input_; }

  // Text set on a token after lexing (WritableToken::setText), which nothing in arbc or in
  // ANTLR's parsing path does; kept here so that a token stays 40 bytes.
  void set_text(const void* token, const std::string& text) { texts_[token] = text; }
  const std::string* text(const void* token) const;

 private:
  antlr4::TokenSource* source_;
  antlr4::CharStream* input_;
  std::unordered_map<const void*, std::string> texts_;
  std::vector<std::unique_ptr<std::byte[]>> blocks_;
  size_t used_ = 0;  // bytes used in blocks_.back()
};

class CompactToken final : public antlr4::WritableToken {
 public:
  // Every value must fit (CompactToken::fits); callers check first.
  CompactToken(TokenArena& arena, size_t type, size_t start, size_t stop, size_t line,
               size_t column);

  static bool fits(size_t type, size_t channel, size_t start, size_t stop, size_t line,
                   size_t column);

  // Only from an arena; deleting through the token stream's unique_ptr runs the destructor and
  // leaves the memory to the arena.
  static void* operator new(size_t bytes, TokenArena& arena) { return arena.allocate(bytes); }
  static void operator delete(void*, TokenArena&) {}
  static void operator delete(void*) {}
  static void* operator new(size_t) = delete;

  std::string getText() const override;
  size_t getType() const override { return type_; }
  size_t getLine() const override { return line_; }
  size_t getCharPositionInLine() const override { return column_; }
  size_t getChannel() const override { return channel_; }
  size_t getTokenIndex() const override { return index_ == UINT32_MAX ? INVALID_INDEX : index_; }
  size_t getStartIndex() const override { return start_; }
  size_t getStopIndex() const override { return stop_; }
  antlr4::TokenSource* getTokenSource() const override { return arena_->source(); }
  antlr4::CharStream* getInputStream() const override { return arena_->input(); }
  std::string toString() const override;

  // The token stream sets the index; nothing sets the others after lexing. A value that does
  // not fit throws std::out_of_range rather than being cut.
  void setText(const std::string& text) override;
  void setType(size_t type) override;
  void setLine(size_t line) override;
  void setCharPositionInLine(size_t column) override;
  void setChannel(size_t channel) override;
  void setTokenIndex(size_t index) override;

 private:
  TokenArena* arena_;
  uint32_t start_;
  uint32_t stop_;
  uint32_t line_;
  uint32_t column_;
  uint32_t index_ = UINT32_MAX;  // "not yet in a stream", as CommonToken's -1
  uint16_t type_;                // the grammar has about 100 token types
  uint8_t channel_ = antlr4::Token::DEFAULT_CHANNEL;
  bool has_text_ = false;  // the arena holds text set by setText
};

// The spec lexer, emitting CompactTokens from its own arena (CommonTokens for EOF and for a
// position beyond 32 bits, which a spec never reaches).
class CompactTokenLexer : public arbc_grammar::ArbcLexer {
 public:
  // Also gives the lexer a DFA cache of its thread's own (thread_dfa.h): use it on one thread.
  explicit CompactTokenLexer(antlr4::CharStream* input);

  using arbc_grammar::ArbcLexer::emit;
  antlr4::Token* emit() override;

 private:
  TokenArena arena_;
};

}  // namespace arbc::frontend
