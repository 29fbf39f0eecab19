#include "compiler/codegen/lua_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace arbc::codegen {
namespace {

TEST(LuaTextTest, StringsEscapeQuotesControlsAndHighBytes) {
  EXPECT_EQ(lua_string("take"), "\"take\"");
  EXPECT_EQ(lua_string("a\"b\\c\nd"), "\"a\\\"b\\\\c\\nd\"");
  EXPECT_EQ(lua_string("\x01\xc3\xa9"), "\"\\001\\195\\169\"");
}

TEST(LuaTextTest, FloatsReadBackExactlyAndStayFloats) {
  EXPECT_EQ(lua_float(0.4), "0.4");
  EXPECT_EQ(lua_float(5), "5.0");
  EXPECT_EQ(lua_float(-0.5), "-0.5");
  EXPECT_EQ(lua_float(1e100), "1e+100");
  EXPECT_EQ(lua_float(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(lua_float(INFINITY), "(1/0)");
  EXPECT_EQ(lua_float(NAN), "(0/0)");
}

TEST(LuaTextTest, LocalNamesNeverCaptureKeywordsOrBuiltins) {
  EXPECT_EQ(lua_local_name("objects"), "objects");
  EXPECT_EQ(lua_local_name("end"), "end_");
  EXPECT_EQ(lua_local_name("len"), "len_");
  EXPECT_EQ(lua_local_name("PortMonitor"), "PortMonitor_");
  EXPECT_EQ(lua_local_name("arbc_emitted"), "arbc_emitted_");
  // One-to-one: a name that already ends in '_' moves too, so `end_` cannot meet `end`.
  EXPECT_EQ(lua_local_name("end_"), "end__");
  EXPECT_NE(lua_local_name("end"), lua_local_name("end_"));
}

TEST(LuaTextTest, FieldsThatAreKeywordsUseBrackets) {
  EXPECT_EQ(lua_field("pos"), ".pos");
  EXPECT_EQ(lua_field("end"), "[\"end\"]");
  EXPECT_EQ(lua_table_key("verb"), "verb = ");
  EXPECT_EQ(lua_table_key("then"), "[\"then\"] = ");
}

}  // namespace
}  // namespace arbc::codegen
