// Monitors written from the core model alone (docs/design.md#pipeline): a lowered app built by
// hand, with no spec, no parser and no AST, gives Lua that runs. What the generator reads is the
// IR the proof encodes.
#include "compiler/codegen/monitor_writer.h"

#include <gtest/gtest.h>

#include "compiler/codegen/testing/lua_monitor_harness.h"
#include "core/body_text.h"
#include "core/body_types.h"

namespace arbc::codegen {
namespace {

using testing::LuaMonitorHarness;
using testing::PortContainer;

model::Body body_of(const std::vector<std::string>& texts, const TypePtr& message) {
  model::Body body;
  for (const std::string& t : texts) {
    std::string err;
    std::optional<model::BodyStmt> s = model::parse_body_stmt(t, &err);
    EXPECT_TRUE(s) << t << ": " << err;
    if (s) body.push_back(std::move(*s));
  }
  EXPECT_TRUE(model::type_body(body, message));
  return body;
}

// Src.m: {i: int, f: float} into Dst.cmd: {lo: float, n: int}, one connection `c`.
lower::LoweredApp hand_built(model::ConnectionKind kind) {
  lower::LoweredApp low;
  model::App& app = low.app;
  app.name = "hand";
  app.spec_file = "hand.spec";
  TypePtr src = parse_type("{i: int, f: float}");
  app.modules.push_back({"Src", "", {{"m", model::Direction::Out, src, {}}}, {}});
  app.modules.push_back(
      {"Dst", "", {{"cmd", model::Direction::In, parse_type("{lo: float, n: int}"), {}}}, {}});
  model::Connection c;
  c.name = kind == model::ConnectionKind::Feed ? "feed_Src_m" : "c";
  c.source = "Src.m";
  c.destination = "Dst.cmd";
  c.kind = kind;
  c.constraint = Constraint::constant(kind != model::ConnectionKind::Feed);
  c.monitor = "monitors/Dst.cmd__" + c.name + ".lua";
  app.connections.push_back(std::move(c));
  lower::MonitorPlan plan;
  plan.kind = kind == model::ConnectionKind::Feed ? lower::MonitorPlan::Kind::Feed
                                                  : lower::MonitorPlan::Kind::Connect;
  plan.message_name = "m";
  low.monitors.push_back(std::move(plan));
  return low;
}

TEST(MonitorWriter, ABodyBuiltByHandNeedsNoAst) {
  lower::LoweredApp low = hand_built(model::ConnectionKind::Connect);
  TypePtr src = low.app.modules[0].ports[0].type;
  low.app.connections[0].body = body_of(
      {"(let 2 k (call min (float (field i msg)) 2.5))", "(accept 3 (< (local k) (field f msg)))",
       "(emit 4 (record lo (local k) n (+ (field i msg) 1)))"},
      src);
  std::string lua = write_monitor(low, low.monitors[0], SpecLines("")).text;
  EXPECT_NE(lua.find("local k = min((m.i + 0.0), 2.5)\n"), std::string::npos) << lua;
  EXPECT_NE(lua.find("if not (k < m.f) then return false end\n"), std::string::npos) << lua;
  EXPECT_NE(lua.find("arbc_emitted = { lo = k, n = m.i + 1 }\n"), std::string::npos) << lua;
  EXPECT_NE(lua.find("local function min(a, ...)"), std::string::npos) << lua;  // its prelude

  PortContainer port;
  LuaMonitorHarness h(lua, "hand.lua", &port, "c");
  ASSERT_EQ(h.load_error(), "");
  h.use_model(low.app, low.app.connections[0]);
  auto r = h.deliver("{ i = 1, f = 3.5 }");
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.accepted);
  // min(1, 2.5) is the float 1.0, as the spec types it; i + 1 stays an integer.
  EXPECT_EQ(r.value, "{lo=1.0, n=2}");
  EXPECT_EQ(h.deliver("{ i = 3, f = 0.5 }").reason, "rejected");
}

TEST(MonitorWriter, ADerivedPredicateBuiltByHandFeedsItsEvent) {
  lower::LoweredApp low = hand_built(model::ConnectionKind::Feed);
  low.app.connections[0].sets = {"e_near"};
  low.app.connections[0].unsets = {"e_near"};
  std::string err;
  std::optional<model::BodyExpr> pred =
      model::parse_body_expr("(< (field f msg) (float (field i msg)))", &err);
  ASSERT_TRUE(pred) << err;
  ASSERT_TRUE(model::type_expr(*pred, low.app.modules[0].ports[0].type));
  low.monitors[0].derived.push_back({"e_near", *pred, std::nullopt, {}});
  std::string lua = write_monitor(low, low.monitors[0], SpecLines("")).text;
  EXPECT_NE(lua.find("return m.f < (m.i + 0.0)\n"), std::string::npos) << lua;

  PortContainer port;
  LuaMonitorHarness h(lua, "feed.lua", &port, "feed_Src_m");
  ASSERT_EQ(h.load_error(), "");
  h.use_model(low.app, low.app.connections[0]);
  EXPECT_FALSE(h.deliver("{ i = 2, f = 0.5 }").accepted);  // a feed never delivers
  EXPECT_EQ(port.present(), std::vector<std::string>{"e_near"});
  h.deliver("{ i = 0, f = 0.5 }");
  EXPECT_EQ(port.present(), std::vector<std::string>{});
}

}  // namespace
}  // namespace arbc::codegen
