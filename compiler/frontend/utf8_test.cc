#include "compiler/frontend/utf8.h"

#include <gtest/gtest.h>

namespace arbc::frontend {
namespace {

TEST(Utf8, AcceptsValidText) {
  EXPECT_FALSE(find_invalid_utf8(""));
  EXPECT_FALSE(find_invalid_utf8("plain ascii\n"));
  EXPECT_FALSE(find_invalid_utf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"));  // é € 😀
}

TEST(Utf8, ReportsTheFirstInvalidByteWithLineAndColumn) {
  auto bad = find_invalid_utf8("ok\nab\xE9x");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->offset, 5u);
  EXPECT_EQ(bad->line, 2);
  EXPECT_EQ(bad->column, 3);
}

TEST(Utf8, RejectsOverlongSurrogatesTruncatedAndOutOfRange) {
  EXPECT_TRUE(find_invalid_utf8("\xC0\xAF"));          // overlong '/'
  EXPECT_TRUE(find_invalid_utf8("\xED\xA0\x80"));      // surrogate U+D800
  EXPECT_TRUE(find_invalid_utf8("\xE2\x82"));          // truncated
  EXPECT_TRUE(find_invalid_utf8("\xF4\x90\x80\x80"));  // above U+10FFFF
  EXPECT_TRUE(find_invalid_utf8("\x80"));              // lone continuation byte
}

}  // namespace
}  // namespace arbc::frontend
