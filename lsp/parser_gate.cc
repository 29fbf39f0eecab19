#include "lsp/parser_gate.h"

#include "compiler/frontend/grammar_info.h"

namespace arbc::lsp {

void ParserGate::before(const std::string& document) {
  bool other = !last_.empty() && document != last_;
  if (other || ++parses_ > kParsesPerReset) {
    frontend::reset_parser_cache();
    ++resets_;
    parses_ = 0;
  }
  last_ = document;
}

int ParserGate::resets() const {
  std::lock_guard lock(mutex_);
  return resets_;
}

}  // namespace arbc::lsp
