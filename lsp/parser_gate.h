// Every parse in the server goes through one gate: the generated ANTLR parser's prediction
// cache is process-wide, so parses must not overlap, and the cache is dropped whenever the
// document changes (and every kParsesPerReset parses of one document) so that a long session
// does not grow it without bound (docs/reliability.md, the spec front end).
#pragma once

#include <mutex>
#include <string>

namespace arbc::lsp {

inline constexpr int kParsesPerReset = 500;

class ParserGate {
 public:
  // Runs f() (which parses `document`) alone.
  template <typename F>
  auto run(const std::string& document, F&& f) {
    std::lock_guard lock(mutex_);
    before(document);
    return f();
  }
  int resets() const;  // how many times the cache was dropped

 private:
  void before(const std::string& document);
  mutable std::mutex mutex_;
  std::string last_;
  int parses_ = 0;
  int resets_ = 0;
};

}  // namespace arbc::lsp
