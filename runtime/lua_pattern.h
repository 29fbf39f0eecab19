// Lua 5.4's string patterns (the reference manual, section 6.4.1), matched with a step budget
// (docs/reliability.md, "A stuck monitor"). Lua's own matcher backtracks without limit inside
// one C call, where the sandbox's instruction hook never fires: a pattern such as
// string.rep("a?", 40) .. string.rep("a", 40) tried on 40 a's runs for hours. This matcher
// implements the same language and answers, but charges every step to a budget and gives up
// with an error when the budget says stop (steps exhausted, wall clock passed, interrupted).
//
// It uses no Lua API: the sandbox's string functions (sandbox_strings.cc) turn its results
// into Lua values and its errors into Lua errors.
#pragma once

#include <cstddef>
#include <cstdint>

namespace arbc {

inline constexpr int kMaxPatternCaptures = 32;  // LUA_MAXCAPTURES
inline constexpr int kMaxPatternDepth = 200;    // MAXCCALLS: recursion of the matcher

// Asked every few thousand steps whether the match may go on; charges them.
struct PatternBudget {
  bool (*charge)(void* context, int64_t steps) = nullptr;  // false: stop now
  void* context = nullptr;
};

class PatternMatcher {
 public:
  static constexpr ptrdiff_t kUnfinished = -1;  // capture length: still open
  static constexpr ptrdiff_t kPosition = -2;    // capture length: a position capture `()`

  struct Capture {
    const char* init = nullptr;
    ptrdiff_t len = 0;
  };

  // The subject and the pattern must outlive the matcher (they are not copied).
  PatternMatcher(const char* subject, size_t subject_len, const char* pattern, size_t pattern_len,
                 PatternBudget budget);

  // Matches the pattern from `p` (a position inside it, e.g. after a `^` anchor) at subject
  // position `s`. Returns the end of the match, or nullptr when it does not match or on error.
  // Captures are reset first.
  const char* match(const char* s, const char* p);

  // Charges the steps not charged yet (the budget is asked only every few thousand steps);
  // false when the budget says stop. Call it after a search.
  bool settle();
  // Points the budget elsewhere (a gmatch iterator lives across calls).
  void set_budget(PatternBudget budget) { budget_ = budget; }

  // Set when the last match stopped on an error: a malformed pattern, or the budget.
  const char* error() const { return error_; }
  bool budget_stopped() const { return budget_stopped_; }

  int captures() const { return level_; }
  const Capture& capture(int i) const { return capture_[i]; }
  const char* subject() const { return src_init_; }
  const char* subject_end() const { return src_end_; }
  const char* pattern_end() const { return p_end_; }

 private:
  const char* do_match(const char* s, const char* p);
  const char* max_expand(const char* s, const char* p, const char* ep);
  const char* min_expand(const char* s, const char* p, const char* ep);
  const char* start_capture(const char* s, const char* p, ptrdiff_t what);
  const char* end_capture(const char* s, const char* p);
  const char* match_capture(const char* s, int index);
  const char* match_balance(const char* s, const char* p);
  const char* match_frontier(const char* s, const char* p);
  const char* class_end(const char* p);
  bool single_match(const char* s, const char* p, const char* ep) const;
  bool step(int64_t n = 1);
  const char* fail(const char* message);

  const char* src_init_;
  const char* src_end_;
  const char* p_end_;
  PatternBudget budget_;
  int64_t unpaid_ = 0;
  int depth_ = 0;
  int level_ = 0;
  Capture capture_[kMaxPatternCaptures];
  const char* error_ = nullptr;
  bool budget_stopped_ = false;
  char message_[64] = {};  // an error text with a number in it
};

// Does Lua's `string.find` treat this pattern as plain text (no special characters)?
bool pattern_is_plain(const char* pattern, size_t len);

}  // namespace arbc
