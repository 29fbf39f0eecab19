#include "compiler/frontend/lexer_dfa.h"

#include <vector>

namespace arbc::frontend {

namespace {

struct ThreadCache {
  std::vector<antlr4::dfa::DFA> dfa;
  antlr4::atn::PredictionContextCache contexts;
};

ThreadCache& thread_cache(const antlr4::atn::ATN& atn) {
  thread_local std::unique_ptr<ThreadCache> cache;
  if (!cache) {
    cache = std::make_unique<ThreadCache>();
    cache->dfa.reserve(atn.getNumberOfDecisions());
    for (size_t i = 0; i < atn.getNumberOfDecisions(); ++i)
      cache->dfa.emplace_back(atn.getDecisionState(i), i);
  }
  return *cache;
}

class ThreadLexerSimulator : public antlr4::atn::LexerATNSimulator {
 public:
  ThreadLexerSimulator(antlr4::Lexer* lexer, ThreadCache& cache)
      : LexerATNSimulator(lexer, lexer->getATN(), cache.dfa, cache.contexts) {}

 protected:
  // The base class's lookup, without its lock: edges are added to this cache only by this
  // thread (under ANTLR's writer lock, which is still taken), so no write can overlap a read.
  antlr4::dfa::DFAState* getExistingTargetState(antlr4::dfa::DFAState* state,
                                                size_t symbol) override {
    if (symbol > MAX_DFA_EDGE) return nullptr;  // beyond ASCII the simulator takes the ATN
    auto edge = state->edges.find(symbol - MIN_DFA_EDGE);
    return edge == state->edges.end() ? nullptr : edge->second;
  }
};

}  // namespace

std::unique_ptr<antlr4::atn::LexerATNSimulator> make_thread_lexer_simulator(antlr4::Lexer* lexer) {
  return std::make_unique<ThreadLexerSimulator>(lexer, thread_cache(lexer->getATN()));
}

}  // namespace arbc::frontend
