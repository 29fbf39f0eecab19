// The claims script's predicates on delivered values (runtime/data_claims.h): what each
// outcome means, and a script that does not match the app is refused at load.
#include "runtime/data_claims.h"

#include <gtest/gtest.h>

#include "core/body_text.h"

namespace arbc {
namespace {

// An app with one assert over `emitted` (`emitted < 10.0`) on M.p's rule r.
model::App one_assert() {
  model::App app;
  model::ArbitratedPort p;
  p.port = "M.p";
  model::Assertion a;
  a.rule = "r";
  std::string err;
  a.emitted = model::parse_body_expr("(< msg 10.0)", &err);
  p.asserts.push_back(a);
  app.arbitrated_ports.push_back(p);
  return app;
}

std::unique_ptr<DataClaims> load(const model::App& app, const std::string& script,
                                 std::string* err) {
  return DataClaims::load(app, script, "claims.lua", err);
}

TEST(DataClaims, EachPredicateJudgesTheDeliveredValue) {
  model::App app = one_assert();
  std::string err, why;
  auto d = load(app, "Claims = { function(emitted) return emitted < 10.0 end }", &err);
  ASSERT_TRUE(d) << err;
  ASSERT_EQ(d->claims().size(), 1u);
  EXPECT_EQ(d->claims()[0].text, "assert M.p: r -> emitted < 10.0 (line 0)");
  EXPECT_EQ(d->evaluate(0, Value(1.0), &why), DataClaims::Outcome::Holds);
  EXPECT_EQ(d->evaluate(0, Value(12.0), &why), DataClaims::Outcome::Fails);
}

// The prelude's "no value" (min_by of an empty list) is its own outcome, as in a monitor.
TEST(DataClaims, AValueThatDoesNotExistIsNoValue) {
  model::App app = one_assert();
  std::string err, why;
  auto d = load(app, "Claims = { function(emitted) PortMonitor.novalue() end }", &err);
  ASSERT_TRUE(d) << err;
  EXPECT_EQ(d->evaluate(0, Value(1.0), &why), DataClaims::Outcome::NoValue);
  EXPECT_NE(why.find("does not exist"), std::string::npos) << why;
}

// A stuck predicate is stopped by the sandbox's budget, as a monitor is, and the next call runs.
TEST(DataClaims, AStuckPredicateIsStopped) {
  model::App app = one_assert();
  std::string err, why;
  auto d = load(app,
                "local n = 0\n"
                "Claims = { function(emitted) n = n + 1; while n == 1 do end; return true end }",
                &err);
  ASSERT_TRUE(d) << err;
  EXPECT_EQ(d->evaluate(0, Value(1.0), &why), DataClaims::Outcome::Error);
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(d->evaluate(0, Value(1.0), &why), DataClaims::Outcome::Holds);
}

TEST(DataClaims, AScriptOfAnotherAppIsRefused) {
  model::App app = one_assert();
  std::string err;
  EXPECT_FALSE(
      load(app, "Claims = { function(e) return true end, function(e) return true end }", &err));
  EXPECT_NE(err.find("defines 2 claims, app.json states 1"), std::string::npos) << err;
  EXPECT_FALSE(load(app, "Claims = ", &err));
  EXPECT_NE(err.find("claims.lua"), std::string::npos) << err;
}

}  // namespace
}  // namespace arbc
