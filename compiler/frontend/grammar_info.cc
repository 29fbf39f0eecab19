#include "compiler/frontend/grammar_info.h"

#include <ArbcLexer.h>
#include <ArbcParser.h>
#include <antlr4-runtime.h>

#include <algorithm>
#include <cctype>

namespace arbc::frontend {

std::vector<std::string> grammar_keywords() {
  std::vector<std::string> out;
  antlr4::ANTLRInputStream input("");
  arbc_grammar::ArbcLexer lexer(&input);
  const antlr4::dfa::Vocabulary& v = lexer.getVocabulary();
  for (size_t t = 0; t <= v.getMaxTokenType(); ++t) {
    std::string literal = v.getLiteralName(t);  // "'module'", or empty
    if (literal.size() < 3 || literal.front() != '\'') continue;
    std::string word = literal.substr(1, literal.size() - 2);
    if (std::isalpha(static_cast<unsigned char>(word[0]))) out.push_back(word);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void reset_parser_cache() {
  // The caches are static members shared by every instance; any instance's simulator clears
  // them. An empty input builds nothing.
  antlr4::ANTLRInputStream input("");
  arbc_grammar::ArbcLexer lexer(&input);
  lexer.getInterpreter<antlr4::atn::LexerATNSimulator>()->clearDFA();
  antlr4::CommonTokenStream tokens(&lexer);
  arbc_grammar::ArbcParser parser(&tokens);
  parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->clearDFA();
}

}  // namespace arbc::frontend
