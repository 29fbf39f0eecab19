#include "import/yarp/lua_parser.h"

#include <gtest/gtest.h>

namespace arbc::yarp {
namespace {

TEST(LuaParser, ReadsAMonitorScript) {
  std::string err;
  auto chunk = parse_lua(R"(
require("yarp")
-- a comment
PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_ball and not e_line")
  return true
end
function PortMonitor.accept(thing)
  local bt = thing:asBottle()
  if bt:get(0):asString() == [[ball]] then
    PortMonitor.setEvent('e_ball', 0.5)
  elseif bt:size() > 2 then return false
  else
    for i = 1, 3 do local x = i ^ 2 .. "s" end
  end
  return true
end
)",
                         &err);
  ASSERT_TRUE(chunk) << err;
  ASSERT_EQ(chunk->body.stats.size(), 3u);
  EXPECT_EQ(chunk->body.stats[1].kind, LuaStat::Kind::Assign);
  const LuaStat& accept = chunk->body.stats[2];
  EXPECT_EQ(accept.kind, LuaStat::Kind::Function);
  ASSERT_TRUE(accept.function);
  EXPECT_EQ(accept.function->params, std::vector<std::string>{"thing"});
  EXPECT_EQ(accept.function->line, 8);
  EXPECT_EQ(accept.function->end_line, 17);
  const LuaStat& if_stat = accept.function->body.stats[1];
  EXPECT_EQ(if_stat.kind, LuaStat::Kind::If);
  EXPECT_EQ(if_stat.exprs.size(), 2u);
  EXPECT_EQ(if_stat.blocks.size(), 3u);
  EXPECT_EQ(if_stat.exprs[0]->items[1]->text, "ball");  // the long string
}

TEST(LuaParser, PrecedenceFollowsLua) {
  std::string err;
  auto chunk = parse_lua("x = 1 + 2 * 3 ^ 2 ^ 1 .. 'a' .. 'b' or not y and z", &err);
  ASSERT_TRUE(chunk) << err;
  const LuaExpr& e = *chunk->body.stats[0].exprs[0];
  EXPECT_EQ(e.text, "or");
  EXPECT_EQ(e.items[0]->text, "..");
  EXPECT_EQ(e.items[0]->items[1]->text, "..");  // right associative
  EXPECT_EQ(e.items[0]->items[0]->text, "+");
  EXPECT_EQ(e.items[1]->text, "and");
  EXPECT_EQ(e.items[1]->items[0]->text, "not");
}

TEST(LuaParser, DecodesEscapes) {
  std::string err;
  auto chunk = parse_lua(R"(s = "a\tb\65\x42\u{263A}\z
                              c")",
                         &err);
  ASSERT_TRUE(chunk) << err;
  EXPECT_EQ(chunk->body.stats[0].exprs[0]->text,
            "a\tbAB\xE2\x98\xBA"
            "c");
}

TEST(LuaParser, ReportsErrorsWithLines) {
  std::string err;
  EXPECT_FALSE(parse_lua("x = 1\nif x then\n", &err));
  EXPECT_EQ(err, "3: 'end' expected near '<eof>'");
  EXPECT_FALSE(parse_lua("x = \"open\n", &err));
  EXPECT_EQ(err, "1: unfinished string");
  EXPECT_FALSE(parse_lua("f() = 1", &err));
  EXPECT_FALSE(parse_lua("x", &err));
  EXPECT_FALSE(parse_lua("x = 3x", &err));
}

TEST(LuaParser, DeepNestingIsAnErrorNotACrash) {
  std::string deep = "x = " + std::string(100000, '(') + "1" + std::string(100000, ')');
  std::string err;
  EXPECT_FALSE(parse_lua(deep, &err));
  EXPECT_NE(err.find("nesting too deep"), std::string::npos);
}

}  // namespace
}  // namespace arbc::yarp
