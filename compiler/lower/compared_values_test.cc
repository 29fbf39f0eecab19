// core/compared_values.h over lowered specs: the constants a spec compares each part of a port's
// messages with, from rule bodies and derived events, through lets, lambdas and len.
#include "core/compared_values.h"

#include <gtest/gtest.h>

#include "compiler/lower/lower_test_util.h"

namespace arbc::lower {
namespace {

using testing::compile_ok;

constexpr const char* kSpec = R"(app parts;
type Obj = { dist: float, kind: string };
module Mic    { out level: { db: float, source: string, count: int }; }
module Eyes   { out objects: list<Obj>; }
module Cmd    { out cmd: float; }
module Motor  { in cmd: float; in grab: Obj; }
const LOUD = 45.0;
event e_loud = Mic.level : level.db > LOUD;
event e_voice = Mic.level : level.source == "voice" and level.count >= -2;
arbitrate Motor.cmd { go: from Cmd.cmd when not e_loud and not e_voice { accept cmd < 2.5; } }
arbitrate Motor.grab {
  near: from Eyes.objects {
    accept len(objects) > 1;
    let o = min_by(objects, x => x.dist);
    accept o.dist <= 0.3 and o.kind != "cup";
    emit o;
  }
}
)";

TEST(ComparedValuesTest, ThresholdsAndStringsOfEachPartOfAPortsMessages) {
  CompiledSpec c = compile_ok(kSpec);
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  model::ComparedParts mic = model::compared_parts(app, "Mic.level");
  EXPECT_EQ(mic["db"].numbers, std::vector<double>{45.0});  // the named constant, folded
  EXPECT_EQ(mic["source"].strings, std::vector<std::string>{"voice"});
  EXPECT_EQ(mic["count"].numbers, std::vector<double>{-2.0});
  EXPECT_EQ(mic.size(), 3u);
  EXPECT_EQ(model::compared_parts(app, "Cmd.cmd")[""].numbers, std::vector<double>{2.5});
  model::ComparedParts eyes = model::compared_parts(app, "Eyes.objects");
  EXPECT_EQ(eyes["len()"].numbers, std::vector<double>{1.0});
  EXPECT_EQ(eyes["[].dist"].numbers, std::vector<double>{0.3});
  EXPECT_EQ(eyes["[].kind"].strings, std::vector<std::string>{"cup"});
  EXPECT_TRUE(model::compared_parts(app, "Motor.cmd").empty());  // an in-port: nothing sent
}

}  // namespace
}  // namespace arbc::lower
