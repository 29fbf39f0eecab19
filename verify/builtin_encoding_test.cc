// Every builtin of the one table (core/builtins.h) has an encoding: verify/body_encoding.cc
// dispatches on the builtin's id, and each builtin here computes its value on constants. A
// builtin added to the table without an encoding, or without a case below, fails this test.
#include <gtest/gtest.h>

#include <map>

#include "core/body_text.h"
#include "verify/body_encoding.h"

namespace arbc::verify {
namespace {

// A call of each builtin on constants, and the value it must have.
const std::map<Builtin, std::pair<std::string, std::string>> kSamples = {
    {Builtin::Len, {"(call len (list 4 5 6))", "3"}},
    {Builtin::MinBy,
     {"(field n (call min_by (list (record d 2.0 n 1) (record d 0.5 n 2)) (lambda o (field d "
      "(param o)))))",
      "2"}},
    {Builtin::MaxBy,
     {"(field n (call max_by (list (record d 2.0 n 1) (record d 0.5 n 2)) (lambda o (field d "
      "(param o)))))",
      "1"}},
    {Builtin::Dist, {"(call dist (call vec3 0.0 0.0 0.0) (call vec3 3.0 4.0 0.0))", "5.0"}},
    {Builtin::Norm, {"(call norm (call vec3 0.0 3.0 4.0))", "5.0"}},
    {Builtin::Abs, {"(call abs (neg 7))", "7"}},
    {Builtin::Min, {"(call min (float 3) 2.5 (float 4))", "2.5"}},
    {Builtin::Max, {"(call max 3 9 4)", "9"}},
    {Builtin::Now, {"(- (call now) (call now))", "0.0"}},  // one unknown time per call
    {Builtin::Age,
     {"(- (call age (record sec 1 nanosec 0)) (call age (record sec 1 nanosec 0)))",
      "0.0"}},  // as now(): the clock is unknown
    {Builtin::Vec3, {"(field y (call vec3 1.0 2.0 3.0))", "2.0"}},
};

TEST(BuiltinEncoding, EveryBuiltinOfTheTableIsEncoded) {
  for (const BuiltinInfo& b : kBuiltins) {
    auto it = kSamples.find(b.id);
    ASSERT_NE(it, kSamples.end()) << "give the builtin " << b.name
                                  << " a sample here and a case in body_encoding.cc's call()";
    const auto& [call, value] = it->second;
    std::string err;
    std::optional<model::BodyStmt> s =
        model::parse_body_stmt("(accept 1 (== " + call + " " + value + "))", &err);
    ASSERT_TRUE(s) << b.name << ": " << err;
    z3::context ctx;
    EncodedBody e = encode_body(ctx, {*s}, SymValue(ctx), "t");
    ASSERT_EQ(e.opaque, "") << b.name;
    if (b.id == Builtin::Now) {  // an unknown value: not always equal to itself a call later
      EXPECT_EQ(e.abstracted, (std::vector<std::string>{"now()", "now()"}));
      continue;
    }
    if (b.id == Builtin::Age) {  // without a clock name, each call reads a clock of its own
      EXPECT_EQ(e.abstracted, (std::vector<std::string>{"stamp_now()", "stamp_now()"}));
      continue;
    }
    z3::solver solver(ctx);
    for (const z3::expr& side : e.side) solver.add(side);
    for (const AcceptTracker& t : e.trackers) solver.add(t.literal);
    solver.add(!e.accepts);
    EXPECT_EQ(solver.check(), z3::unsat) << b.name << ": " << call << " is not always " << value;
  }
}

}  // namespace
}  // namespace arbc::verify
