#include "runtime/same_name.h"

#include <gtest/gtest.h>

#include <string>

namespace arbc {
namespace {

// Every length around the word sizes, equal names and names that differ in exactly one byte
// at each position (the overlapping loads must cover every byte, the first and the last too).
TEST(SameNameTest, AgreesWithStringEqualityAtEveryLengthAndPosition) {
  for (size_t n = 0; n <= 40; ++n) {
    std::string a(n, 'p');
    for (size_t i = 0; i < n; ++i) a[i] = static_cast<char>('a' + i % 26);
    std::string b = a;
    EXPECT_TRUE(same_name(a, b)) << n;
    for (size_t i = 0; i < n; ++i) {
      std::string c = a;
      c[i] = static_cast<char>(c[i] ^ 0x20);
      EXPECT_FALSE(same_name(a, c)) << "length " << n << ", byte " << i;
    }
    EXPECT_FALSE(same_name(a, a + "x")) << n;
    if (n > 0) {
      EXPECT_FALSE(same_name(a, a.substr(0, n - 1))) << n;
    }
  }
}

// Views into longer strings: only the view's bytes count.
TEST(SameNameTest, ComparesOnlyTheViewsBytes) {
  std::string text = "FaceDetector.face";
  EXPECT_TRUE(same_name(std::string_view(text).substr(0, 12), "FaceDetector"));
  EXPECT_TRUE(same_name(std::string_view(text).substr(13), "face"));
  EXPECT_FALSE(same_name(std::string_view(text).substr(0, 13), "FaceDetector"));
}

}  // namespace
}  // namespace arbc
