#include "compiler/frontend/thread_dfa.h"

#include <map>
#include <vector>

namespace arbc::frontend {

namespace {

struct ThreadCache {
  std::vector<antlr4::dfa::DFA> dfa;  // one per decision of the ATN
  antlr4::atn::PredictionContextCache contexts;
};

// This thread's cache for the grammar whose ATN is `atn` (the lexer's and the parser's differ).
ThreadCache& thread_cache(const antlr4::atn::ATN& atn) {
  thread_local std::map<const antlr4::atn::ATN*, std::unique_ptr<ThreadCache>> caches;
  std::unique_ptr<ThreadCache>& cache = caches[&atn];
  if (!cache) {
    cache = std::make_unique<ThreadCache>();
    cache->dfa.reserve(atn.getNumberOfDecisions());
    for (size_t i = 0; i < atn.getNumberOfDecisions(); ++i)
      cache->dfa.emplace_back(atn.getDecisionState(i), i);
  }
  return *cache;
}

// Both lookups are the base classes' without their lock: edges are added to these caches only
// by this thread (under ANTLR's writer lock, which is still taken), so no write overlaps a read.

class ThreadLexerSimulator : public antlr4::atn::LexerATNSimulator {
 public:
  ThreadLexerSimulator(antlr4::Lexer* lexer, ThreadCache& cache)
      : LexerATNSimulator(lexer, lexer->getATN(), cache.dfa, cache.contexts) {}

 protected:
  antlr4::dfa::DFAState* getExistingTargetState(antlr4::dfa::DFAState* state,
                                                size_t symbol) override {
    if (symbol > MAX_DFA_EDGE) return nullptr;  // beyond ASCII the simulator takes the ATN
    auto edge = state->edges.find(symbol - MIN_DFA_EDGE);
    return edge == state->edges.end() ? nullptr : edge->second;
  }
};

class ThreadParserSimulator : public antlr4::atn::ParserATNSimulator {
 public:
  ThreadParserSimulator(antlr4::Parser* parser, ThreadCache& cache)
      : ParserATNSimulator(parser, parser->getATN(), cache.dfa, cache.contexts) {}

 protected:
  antlr4::dfa::DFAState* getExistingTargetState(antlr4::dfa::DFAState* previous,
                                                size_t symbol) override {
    auto edge = previous->edges.find(symbol);
    return edge == previous->edges.end() ? nullptr : edge->second;
  }
};

}  // namespace

std::unique_ptr<antlr4::atn::LexerATNSimulator> make_thread_lexer_simulator(antlr4::Lexer* lexer) {
  return std::make_unique<ThreadLexerSimulator>(lexer, thread_cache(lexer->getATN()));
}

std::unique_ptr<antlr4::atn::ParserATNSimulator> make_thread_parser_simulator(
    antlr4::Parser* parser) {
  return std::make_unique<ThreadParserSimulator>(parser, thread_cache(parser->getATN()));
}

}  // namespace arbc::frontend
