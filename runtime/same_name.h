// Name equality for the lookups on the message path (a module by name on Runtime::publish, an
// output port by name on every publish). Names are short, and a call into the C library's
// memcmp (through the PLT, then its dispatch on the processor's features) cost more than the
// comparison itself: it was an eighth of bare_delivery's time. Names of 4 to 16 bytes compare
// as two overlapping words, inline, of 17 to 32 as four; others fall back to memcmp. The
// runtime checks find a record's names with it too (runtime/name_map.h).
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

namespace arbc {

namespace same_name_detail {
template <class Word>
Word load(const char* p) {
  Word w;
  std::memcpy(&w, p, sizeof w);
  return w;
}
// The first and the last sizeof(Word) bytes of a and b (n bytes each, sizeof(Word) <= n <=
// 2 * sizeof(Word)), which together cover every byte.
template <class Word>
bool same_words(const char* a, const char* b, size_t n) {
  Word head = load<Word>(a) ^ load<Word>(b);
  Word tail = load<Word>(a + n - sizeof(Word)) ^ load<Word>(b + n - sizeof(Word));
  return (head | tail) == 0;
}
}  // namespace same_name_detail

inline bool same_name(std::string_view a, std::string_view b) {
  size_t n = a.size();
  if (n != b.size()) return false;
  if (n >= 8 && n <= 16) return same_name_detail::same_words<uint64_t>(a.data(), b.data(), n);
  if (n > 16 && n <= 32)  // "Module.port" often is: its first 16 bytes and its last 16
    return same_name_detail::same_words<uint64_t>(a.data(), b.data(), 16) &&
           same_name_detail::same_words<uint64_t>(a.data() + n - 16, b.data() + n - 16, 16);
  if (n >= 4 && n < 8) return same_name_detail::same_words<uint32_t>(a.data(), b.data(), n);
  return n == 0 || std::memcmp(a.data(), b.data(), n) == 0;
}

}  // namespace arbc
