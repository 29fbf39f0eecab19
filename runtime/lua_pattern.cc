#include "runtime/lua_pattern.h"

#include <cctype>
#include <cstdio>
#include <cstring>

namespace arbc {

namespace {

constexpr int64_t kChargeEvery = 4096;  // steps between two questions to the budget

// `%a`, `%d`, ... of the reference manual (C locale); an upper-case letter is the complement;
// any other character after `%` stands for itself.
bool match_class(unsigned char c, unsigned char cl) {
  bool res;
  switch (std::tolower(cl)) {
    case 'a':
      res = std::isalpha(c);
      break;
    case 'c':
      res = std::iscntrl(c);
      break;
    case 'd':
      res = std::isdigit(c);
      break;
    case 'g':
      res = std::isgraph(c);
      break;
    case 'l':
      res = std::islower(c);
      break;
    case 'p':
      res = std::ispunct(c);
      break;
    case 's':
      res = std::isspace(c);
      break;
    case 'u':
      res = std::isupper(c);
      break;
    case 'w':
      res = std::isalnum(c);
      break;
    case 'x':
      res = std::isxdigit(c);
      break;
    default:
      return cl == c;
  }
  return std::isupper(cl) ? !res : res;
}

// `[set]` from p (at '[') to ec (at its ']').
bool match_bracket(unsigned char c, const char* p, const char* ec) {
  bool sig = true;
  if (p[1] == '^') {
    sig = false;
    ++p;
  }
  while (++p < ec) {
    if (*p == '%') {
      ++p;
      if (match_class(c, static_cast<unsigned char>(*p))) return sig;
    } else if (p[1] == '-' && p + 2 < ec) {
      p += 2;
      if (static_cast<unsigned char>(p[-2]) <= c && c <= static_cast<unsigned char>(*p)) return sig;
    } else if (static_cast<unsigned char>(*p) == c) {
      return sig;
    }
  }
  return !sig;
}

}  // namespace

PatternMatcher::PatternMatcher(const char* subject, size_t subject_len, const char* pattern,
                               size_t pattern_len, PatternBudget budget)
    : src_init_(subject),
      src_end_(subject + subject_len),
      p_end_(pattern + pattern_len),
      budget_(budget) {}

const char* PatternMatcher::match(const char* s, const char* p) {
  level_ = 0;
  depth_ = 0;
  error_ = nullptr;
  budget_stopped_ = false;
  return do_match(s, p);
}

bool PatternMatcher::settle() {
  if (unpaid_ == 0 || !budget_.charge) return true;
  int64_t paid = unpaid_;
  unpaid_ = 0;
  if (budget_.charge(budget_.context, paid)) return true;
  budget_stopped_ = true;
  fail("stopped by the budget");
  return false;
}

bool PatternMatcher::step(int64_t n) {
  unpaid_ += n;
  return unpaid_ < kChargeEvery || settle();
}

const char* PatternMatcher::fail(const char* message) {
  if (!error_) error_ = message;
  return nullptr;
}

// The end of the single-character class at p: `x`, `%x`, `.` or `[set]`.
const char* PatternMatcher::class_end(const char* p) {
  char c = *p++;
  if (c == '%') {
    if (p >= p_end_) return fail("malformed pattern (ends with '%')");
    return p + 1;
  }
  if (c == '[') {
    if (p < p_end_ && *p == '^') ++p;
    do {  // the first character after '[' (or "[^") is never the closing ']'
      if (p >= p_end_) return fail("malformed pattern (missing ']')");
      char d = *p++;
      if (d == '%' && p < p_end_) ++p;
    } while (p >= p_end_ || *p != ']');
    return p + 1;
  }
  return p;
}

bool PatternMatcher::single_match(const char* s, const char* p, const char* ep) const {
  if (s >= src_end_) return false;
  unsigned char c = static_cast<unsigned char>(*s);
  switch (*p) {
    case '.':
      return true;
    case '%':
      return match_class(c, static_cast<unsigned char>(p[1]));
    case '[':
      return match_bracket(c, p, ep - 1);
    default:
      return static_cast<unsigned char>(*p) == c;
  }
}

const char* PatternMatcher::max_expand(const char* s, const char* p, const char* ep) {
  ptrdiff_t i = 0;
  while (single_match(s + i, p, ep)) {
    ++i;
    if (!step()) return nullptr;
  }
  for (; i >= 0; --i) {  // the longest run first, then one shorter each time
    const char* r = do_match(s + i, ep + 1);
    if (r || error_) return r;
  }
  return nullptr;
}

const char* PatternMatcher::min_expand(const char* s, const char* p, const char* ep) {
  for (;;) {
    const char* r = do_match(s, ep + 1);
    if (r || error_) return r;
    if (!single_match(s, p, ep)) return nullptr;
    ++s;
  }
}

const char* PatternMatcher::start_capture(const char* s, const char* p, ptrdiff_t what) {
  if (level_ >= kMaxPatternCaptures) return fail("too many captures");
  capture_[level_].init = s;
  capture_[level_].len = what;
  ++level_;
  const char* r = do_match(s, p);
  if (!r) --level_;
  return r;
}

const char* PatternMatcher::end_capture(const char* s, const char* p) {
  int l = level_ - 1;
  while (l >= 0 && capture_[l].len != kUnfinished) --l;
  if (l < 0) return fail("invalid pattern capture");
  capture_[l].len = s - capture_[l].init;
  const char* r = do_match(s, p);
  if (!r) capture_[l].len = kUnfinished;
  return r;
}

// `%1` .. `%9`: the text of a closed capture again.
const char* PatternMatcher::match_capture(const char* s, int digit) {
  int l = digit - '1';
  if (l < 0 || l >= level_ || capture_[l].len == kUnfinished) {
    std::snprintf(message_, sizeof message_, "invalid capture index %%%d", l + 1);
    return fail(message_);
  }
  ptrdiff_t len = capture_[l].len;
  if (len < 0 || src_end_ - s < len) return nullptr;  // a position capture matches no text
  if (!step(1 + len / 16)) return nullptr;
  return std::memcmp(capture_[l].init, s, static_cast<size_t>(len)) == 0 ? s + len : nullptr;
}

// `%bxy`: a balanced run from x to its matching y.
const char* PatternMatcher::match_balance(const char* s, const char* p) {
  if (p + 1 >= p_end_) return fail("malformed pattern (missing arguments to '%b')");
  if (s >= src_end_ || *s != *p) return nullptr;
  char open = p[0], close = p[1];
  int depth = 1;
  while (++s < src_end_) {
    if (!step()) return nullptr;
    if (*s == close) {
      if (--depth == 0) return s + 1;
    } else if (*s == open) {
      ++depth;
    }
  }
  return nullptr;
}

// `%f[set]`: the empty string where the character before is outside the set and the one at `s`
// inside (the string's ends count as '\0'). The pattern after the set, or nullptr.
const char* PatternMatcher::match_frontier(const char* s, const char* p) {
  if (p >= p_end_ || *p != '[') return fail("missing '[' after '%f' in pattern");
  const char* ep = class_end(p);
  if (!ep) return nullptr;
  unsigned char previous = s == src_init_ ? 0 : static_cast<unsigned char>(s[-1]);
  unsigned char current = s < src_end_ ? static_cast<unsigned char>(*s) : 0;
  bool at_frontier = !match_bracket(previous, p, ep - 1) && match_bracket(current, p, ep - 1);
  return at_frontier ? ep : nullptr;
}

// Lua's `match`, with its tail calls as loop iterations; recursion only where Lua recurses.
const char* PatternMatcher::do_match(const char* s, const char* p) {
  if (error_) return nullptr;
  if (depth_ >= kMaxPatternDepth) return fail("pattern too complex");
  ++depth_;
  const char* result = nullptr;
  for (;;) {
    if (!step()) break;
    if (p == p_end_) {
      result = s;
      break;
    }
    bool simple = false;  // a single-character class with an optional suffix
    switch (*p) {
      case '(':
        result = p + 1 < p_end_ && p[1] == ')' ? start_capture(s, p + 2, kPosition)
                                               : start_capture(s, p + 1, kUnfinished);
        break;
      case ')':
        result = end_capture(s, p + 1);
        break;
      case '$':
        simple = p + 1 != p_end_;  // not at the end: a literal '$'
        if (!simple) result = s == src_end_ ? s : nullptr;
        break;
      case '%':
        if (p + 1 < p_end_ && p[1] == 'b') {
          s = match_balance(s, p + 2);
          if (s) {
            p += 4;
            continue;
          }
        } else if (p + 1 < p_end_ && p[1] == 'f') {
          p = match_frontier(s, p + 2);
          if (p) continue;
        } else if (p + 1 < p_end_ && std::isdigit(static_cast<unsigned char>(p[1]))) {
          s = match_capture(s, p[1]);
          if (s) {
            p += 2;
            continue;
          }
        } else {
          simple = true;
        }
        break;
      default:
        simple = true;
    }
    if (!simple) break;
    const char* ep = class_end(p);
    if (!ep) break;
    char suffix = ep < p_end_ ? *ep : '\0';
    if (!single_match(s, p, ep)) {
      if (suffix == '*' || suffix == '?' || suffix == '-') {  // may match zero times
        p = ep + 1;
        continue;
      }
      break;
    }
    if (suffix == '?') {
      result = do_match(s + 1, ep + 1);
      if (result || error_) break;
      p = ep + 1;
      continue;
    }
    if (suffix == '+' || suffix == '*') {
      result = max_expand(suffix == '+' ? s + 1 : s, p, ep);
      break;
    }
    if (suffix == '-') {
      result = min_expand(s, p, ep);
      break;
    }
    ++s;  // no suffix: one character matched
    p = ep;
  }
  --depth_;
  return error_ ? nullptr : result;
}

bool pattern_is_plain(const char* pattern, size_t len) {
  for (size_t i = 0; i < len; ++i)
    if (std::strchr("^$*+?.([%-", pattern[i]) && pattern[i] != '\0') return false;
  return true;
}

}  // namespace arbc
