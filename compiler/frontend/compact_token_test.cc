#include "compiler/frontend/compact_token.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "tests/support/tree_paths.h"

namespace arbc::frontend {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Lexes `text` with `Lexer` and returns the stream's tokens' descriptions.
template <typename Lexer>
std::vector<std::string> lex(const std::string& text, size_t* compact = nullptr) {
  antlr4::ANTLRInputStream input(text);
  Lexer lexer(&input);
  lexer.removeErrorListeners();
  antlr4::CommonTokenStream stream(&lexer);
  stream.fill();
  std::vector<std::string> out;
  for (size_t i = 0; i < stream.size(); ++i) {
    antlr4::Token* t = stream.get(i);
    if (compact && dynamic_cast<CompactToken*>(t)) ++*compact;
    out.push_back(t->toString() + " type=" + std::to_string(t->getType()) +
                  " line=" + std::to_string(t->getLine()) +
                  " col=" + std::to_string(t->getCharPositionInLine()) +
                  " ch=" + std::to_string(t->getChannel()) +
                  " idx=" + std::to_string(t->getTokenIndex()) + " text=" + t->getText() +
                  " src=" + std::to_string(t->getInputStream() == &input) +
                  std::to_string(t->getTokenSource() == &lexer));
  }
  return out;
}

TEST(CompactToken, LexesThePaperSpecExactlyAsCommonTokensDo) {
  // A spec with comments, strings, durations, non-ASCII text and every kind of declaration.
  std::string text =
      read(arbc::testing::source_dir() + "/specs/table_clean.spec") +
      "\n// caf\xC3\xA9 \xE2\x82\xAC\nconst \xC3\xA9t\xC3\xA9 = \"\xF0\x9F\x98\x80\";\n";
  size_t compact = 0;
  std::vector<std::string> expected = lex<arbc_grammar::ArbcLexer>(text);
  std::vector<std::string> got = lex<CompactTokenLexer>(text, &compact);
  ASSERT_GT(expected.size(), 500u);
  EXPECT_EQ(got, expected);
  EXPECT_EQ(compact, expected.size() - 1);  // all but EOF
}

TEST(CompactToken, LexersOnSeveralThreadsAtOnceEachGetTheSameTokens) {
  // Each thread's lexers read a DFA cache of that thread's own (thread_dfa.h), built as they go.
  std::string text = read(arbc::testing::source_dir() + "/specs/table_clean.spec");
  std::vector<std::string> expected = lex<arbc_grammar::ArbcLexer>(text);
  std::vector<std::vector<std::string>> got(4);
  std::vector<std::thread> threads;
  for (auto& out : got)
    threads.emplace_back([&text, &out] {
      for (int round = 0; round < 3; ++round) out = lex<CompactTokenLexer>(text);
    });
  for (std::thread& t : threads) t.join();
  for (const auto& out : got) EXPECT_EQ(out, expected);
}

TEST(CompactToken, IsFortyBytesAndKeepsTextSetAfterLexing) {
  EXPECT_EQ(sizeof(CompactToken), 40u);
  antlr4::ANTLRInputStream input("app x;");
  CompactTokenLexer lexer(&input);
  std::unique_ptr<antlr4::Token> token = lexer.nextToken();
  auto* compact = dynamic_cast<CompactToken*>(token.get());
  ASSERT_NE(compact, nullptr);
  EXPECT_EQ(compact->getText(), "app");
  compact->setText("renamed");
  EXPECT_EQ(compact->getText(), "renamed");
  EXPECT_EQ(compact->getStopIndex(), 2u);  // the range is still the lexed one
}

TEST(CompactToken, RefusesValuesItCannotHoldRatherThanCuttingThem) {
  antlr4::ANTLRInputStream input("app x;");
  CompactTokenLexer lexer(&input);
  std::unique_ptr<antlr4::Token> token = lexer.nextToken();
  auto* compact = dynamic_cast<CompactToken*>(token.get());
  ASSERT_NE(compact, nullptr);
  size_t type = compact->getType();
  EXPECT_THROW(compact->setType(70000), std::out_of_range);
  EXPECT_THROW(compact->setLine(size_t{1} << 40), std::out_of_range);
  EXPECT_THROW(compact->setChannel(300), std::out_of_range);
  EXPECT_EQ(compact->getType(), type);
  EXPECT_EQ(compact->getLine(), 1u);
  EXPECT_EQ(compact->getChannel(), antlr4::Token::DEFAULT_CHANNEL);
  compact->setTokenIndex(INVALID_INDEX);
  EXPECT_EQ(compact->getTokenIndex(), INVALID_INDEX);
  EXPECT_FALSE(CompactToken::fits(1, 0, 0, size_t{1} << 32, 1, 0));
  EXPECT_TRUE(CompactToken::fits(1, 0, 0, 3, 1, 0));
}

}  // namespace
}  // namespace arbc::frontend
