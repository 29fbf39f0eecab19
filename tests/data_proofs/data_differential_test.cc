// The data encoding (verify/body_encoding.h) against the runtime's Lua monitors: random rules,
// compiled by arbc and run in a real Lua 5.4 sandbox, on random messages. For every message
// the encoding must say exactly what the monitor does: accept or drop, and the value
// delivered. Every builtin of the language appears (docs/checks.md#message-data).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "compiler/codegen/embedded_target.h"
#include "compiler/lower/compile_spec.h"
#include "runtime/lua_monitor.h"
#include "verify/body_encoding.h"
#include "verify/data_query.h"

namespace arbc::verify {
namespace {

constexpr int kBound = 4;

const char* kPrelude = R"(app diff;
type Item = { d: float, k: int, t: string };
type Msg = { a: float, b: int, s: string, p: vec3, xs: list<Item> };
type Cmd = { verb: string, v: float };
const C = 0.5;
module Src { out m: Msg; }
module Dst { in cmd: Cmd; }
arbitrate Dst.cmd {
  r: from Src.m {
)";

// Random expressions of the spec language over the message `m`, by type.
class Gen {
 public:
  explicit Gen(unsigned seed) : rng_(seed) {}
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  std::string flt(int d) {
    static const char* lits[] = {"0.5", "-1.0", "0.25", "2.0", "0.0", "C"};
    if (d <= 0) {
      switch (pick(4)) {
        case 0:
          return "m.a";
        case 1:
          return "m.p.x";
        case 2:
          return lits[pick(6)];
        default:
          return "m.p.z";
      }
    }
    switch (pick(15)) {
      case 0:
        return "(" + flt(d - 1) + " + " + flt(d - 1) + ")";
      case 1:
        return "(" + flt(d - 1) + " - " + num(d - 1) + ")";
      case 2:
        return "(" + flt(d - 1) + " * " + flt(d - 1) + ")";
      case 3:
        return "abs(" + flt(d - 1) + ")";
      case 4:
        return "min(" + flt(d - 1) + ", " + num(d - 1) + ")";
      case 5:
        return "max(" + num(d - 1) + ", " + flt(d - 1) + ", " + flt(d - 1) + ")";
      case 6:
        return "min_by(m.xs, o => " + key() + ").d";
      case 7:
        return "max_by(m.xs, o => " + key() + ").d";
      case 8:
        return "m.xs[" + idx() + "].d";
      case 9:
        return "norm(" + vec(d - 1) + ")";
      case 10:
        return "dist(" + vec(d - 1) + ", " + vec(d - 1) + ")";
      case 11:
        return "(" + flt(d - 1) + " / 2)";
      case 12:
        return "(" + num(d - 1) + " % 2.0)";
      case 13:
        return "-" + flt(0);
      default:
        return "vec3(" + flt(d - 1) + ", 0.0, 1.0).x";
    }
  }
  std::string key() {
    switch (pick(4)) {
      case 0:
        return "o.d";
      case 1:
        return "o.k";
      case 2:
        return "abs(o.d - m.a)";
      default:
        return "-o.d";
    }
  }
  std::string idx() {
    switch (pick(3)) {
      case 0:
        return std::to_string(pick(5));
      case 1:
        return "m.b";
      default:
        return "len(m.xs) - 1";
    }
  }
  std::string integer(int d) {
    if (d <= 0) {
      switch (pick(3)) {
        case 0:
          return "m.b";
        case 1:
          return "len(m.xs)";
        default:
          return std::to_string(pick(5) - 1);
      }
    }
    switch (pick(8)) {
      case 0:
        return "(" + integer(d - 1) + " + " + integer(d - 1) + ")";
      case 1:
        return "(" + integer(d - 1) + " * " + integer(d - 1) + ")";
      case 2:
        return "abs(" + integer(d - 1) + ")";
      case 3:
        return "min(" + integer(d - 1) + ", " + integer(d - 1) + ")";
      case 4:
        return "max_by(m.xs, o => " + key() + ").k";
      case 5:
        return "(" + integer(d - 1) + " % 3)";
      case 6:
        return "m.xs[" + idx() + "].k";
      default:
        return "max(" + integer(d - 1) + ", 1)";
    }
  }
  std::string num(int d) { return pick(2) ? flt(d) : integer(d); }
  std::string str(int d) {
    switch (pick(d > 0 ? 5 : 3)) {
      case 0:
        return "m.s";
      case 1:
        return pick(2) ? "\"go\"" : "\"stop\"";
      case 2:
        return "\"\"";
      case 3:
        return "(" + str(d - 1) + " + " + str(d - 1) + ")";
      default:
        return "min_by(m.xs, o => " + key() + ").t";
    }
  }
  std::string vec(int d) {
    switch (pick(d > 0 ? 5 : 2)) {
      case 0:
        return "m.p";
      case 1:
        return "vec3(" + flt(0) + ", " + flt(0) + ", 0.5)";
      case 2:
        return "(" + vec(d - 1) + " + m.p)";
      case 3:
        return "(" + vec(d - 1) + " * 2.0)";
      default:
        return "-" + vec(0);
    }
  }
  std::string cmp(int d) {
    static const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
    switch (pick(5)) {
      case 0:
        return num(d) + " " + ops[pick(6)] + " " + num(d);
      case 1:
        return str(d) + (pick(2) ? " == " : " != ") + str(d);
      case 2:
        return vec(d) + " == " + vec(d);
      case 3:
        return "[" + num(0) + ", " + num(0) + "] != [" + num(0) + "]";
      default:
        return "len(m.xs) " + std::string(ops[pick(6)]) + " " + std::to_string(pick(4));
    }
  }
  std::string boolean(int d) {
    if (d <= 0) return cmp(0);
    switch (pick(4)) {
      case 0:
        return "(" + boolean(d - 1) + " and " + boolean(d - 1) + ")";
      case 1:
        return "(" + boolean(d - 1) + " or " + boolean(d - 1) + ")";
      case 2:
        return "not (" + boolean(d - 1) + ")";
      default:
        return cmp(d - 1);
    }
  }
  std::string emit(int d) { return "emit { verb: " + str(d) + ", v: " + flt(d) + " };"; }

  // A body: a first emit (every path delivers a Cmd), then random statements.
  std::string body() {
    std::string out = "    emit { verb: \"none\", v: 0.0 };\n";
    int n = 1 + pick(4);
    for (int i = 0; i < n; ++i) {
      switch (pick(4)) {
        case 0:
          out += "    accept " + boolean(2) + ";\n";
          break;
        case 1:
          out += "    let x" + std::to_string(i) + " = " + flt(2) + ";\n";
          out += "    accept x" + std::to_string(i) + " " + (pick(2) ? "<" : ">=") + " " + flt(1) +
                 ";\n";
          break;
        case 2:
          out += "    if " + boolean(1) + " { " + emit(1) + " } else { " +
                 (pick(2) ? emit(1) : "accept " + boolean(1) + ";") + " }\n";
          break;
        default:
          out += "    " + emit(2) + "\n";
      }
    }
    return out;
  }

  Value message() {
    static const double floats[] = {-1, -0.5, 0, 0.25, 0.5, 1, 2};
    static const char* strings[] = {"", "go", "stop", "x"};
    auto f = [&] { return Value(floats[pick(7)]); };
    ValueList xs;
    int n = pick(kBound + 1);
    for (int i = 0; i < n; ++i)
      xs.push_back(
          Value::record({{"d", f()}, {"k", Value(pick(5) - 1)}, {"t", Value(strings[pick(4)])}}));
    return Value::record({{"a", f()},
                          {"b", Value(pick(5) - 1)},
                          {"s", Value(strings[pick(4)])},
                          {"p", Value::vec3(floats[pick(7)], floats[pick(7)], floats[pick(7)])},
                          {"xs", Value(std::move(xs))}});
  }

 private:
  std::mt19937 rng_;
};

class NullHost : public MonitorHost {
 public:
  Nanos now() override { return Nanos(0); }
  void set_event(std::string_view, std::optional<Nanos>) override {}
  void unset_event(std::string_view) override {}
  bool has_event(std::string_view) override { return false; }
  bool set_constraint(std::string_view, std::string*) override { return true; }
  std::string get_constraint() override { return "true"; }
  void set_trig_interval(Nanos) override {}
  void print(const std::string&) override {}
};

// What the encoding says about one concrete message: accepted, and the value delivered.
struct Encoded {
  bool accepted = false;
  Value emitted;
};

Encoded decide(z3::context& ctx, const model::Body& body, const Type& msg_type, const Value& msg) {
  SymValue m = constant_value(ctx, msg, msg_type, kBound);
  EncodedBody e = encode_body(ctx, body, m, "r");
  EXPECT_EQ(e.opaque, "");
  z3::solver s(ctx);
  for (const z3::expr& x : e.side) s.add(x);
  for (const AcceptTracker& t : e.trackers) s.add(t.literal);
  s.push();
  s.add(e.accepts);
  Encoded out;
  out.accepted = s.check() == z3::sat;
  if (out.accepted) {
    out.emitted = concrete(s.get_model(), *e.emitted);
    s.pop();
    s.add(!e.accepts);
    EXPECT_EQ(s.check(), z3::unsat) << "the encoding both accepts and rejects";
  }
  return out;
}

bool close_values(const Value& a, const Value& b) {
  if (a.is_number() && b.is_number())
    return std::fabs(a.as_float() - b.as_float()) <= 1e-9 * (1 + std::fabs(a.as_float()));
  if (a.is_record() && b.is_record()) {
    if (a.as_record().size() != b.as_record().size()) return false;
    for (const auto& [k, v] : a.as_record())
      if (!close_values(v, b[k])) return false;
    return true;
  }
  return a == b;
}

TEST(DataDifferential, EncodingAgreesWithLuaMonitors) {
  z3::context ctx;
  Gen gen(20261123);
  int cases = 0, accepted = 0, rules = 0;
  std::set<std::string> builtins_seen;
  for (int r = 0; r < 160; ++r) {
    std::string body = gen.body();
    std::string spec = std::string(kPrelude) + body + "  }\n}\n";
    lower::CompiledSpec c = lower::compile_spec_text(spec, "diff.spec");
    if (!c.ok) continue;  // a random body sema rejects (e.g. a type clash): not a case
    ++rules;
    for (const char* b : {"len(", "min_by(", "max_by(", "dist(", "norm(", "abs(", "min(", "max(",
                          "vec3(", "%", "/", "[", " + \""})
      if (body.find(b) != std::string::npos) builtins_seen.insert(b);
    codegen::CodegenResult g = codegen::EmbeddedTarget().generate(*c.lowered);
    const model::App& app = c.lowered->app;
    const model::Connection& conn = app.connections.front();
    ASSERT_TRUE(conn.body.has_value());
    std::string lua;
    for (const auto& f : g.files)
      if (f.path == conn.monitor) lua = f.content;
    NullHost host;
    std::string err;
    auto mon = LuaMonitor::load(lua, conn.monitor, SandboxLimits{}, &host, &err);
    ASSERT_TRUE(mon) << err;
    bool created = false;
    ASSERT_TRUE(mon->create({conn.source, conn.destination, conn.name}, &created).ok());
    const Type& msg_type = *app.find_port("Src.m")->type;
    const Type& cmd_type = *app.find_port("Dst.cmd")->type;
    for (int k = 0; k < 12; ++k) {
      Value msg = gen.message();
      bool lua_accepted = false;
      std::string reason;
      LuaCall call = mon->accept(msg, &lua_accepted, &reason);
      Value delivered;
      if (call.ok() && lua_accepted) call = mon->update(cmd_type, &delivered);
      lua_accepted = lua_accepted && call.ok();
      EXPECT_NE(call.status, LuaCall::Status::Error) << call.error;
      Encoded enc = decide(ctx, *conn.body, msg_type, msg);
      ++cases;
      accepted += lua_accepted;
      ASSERT_EQ(enc.accepted, lua_accepted) << "body:\n"
                                            << body << "message: " << spec_value_text(msg);
      if (lua_accepted) {
        ASSERT_TRUE(close_values(enc.emitted, delivered))
            << "body:\n"
            << body << "message: " << spec_value_text(msg)
            << "\nZ3: " << spec_value_text(enc.emitted) << "\nLua: " << spec_value_text(delivered);
      }
    }
  }
  EXPECT_GE(cases, 1000);
  EXPECT_GE(accepted, cases / 10) << "too few accepted messages to compare deliveries";
  EXPECT_GE(rules, 100);
  EXPECT_EQ(builtins_seen.size(), 13u) << "every builtin and operator is exercised";
}

}  // namespace
}  // namespace arbc::verify
