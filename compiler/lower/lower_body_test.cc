// Bodies as IR (compiler/lower/lower_body.h): the explicit int-to-float conversions, and the
// IR's types (core/body_types.h) against sema's on every spec in the repository, as lowered and
// as read back from app.json.
#include "compiler/lower/lower_body.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "compiler/frontend/frontend.h"
#include "compiler/lower/lower.h"
#include "compiler/lower/lower_test_util.h"
#include "core/app_json.h"
#include "core/body_text.h"
#include "tests/support/tree_paths.h"

namespace arbc::lower {
namespace {

using testing::compile_ok;
using testing::find_connection;

const char* kConversions = R"(app conv;
module Src { out m: {i: int, f: float, xs: list<int>}; }
module Dst { in cmd: {lo: float, v: vec3, ys: list<float>, s: float, q: float}; }
const K = 3;
connect Src.m -> Dst.cmd {
  accept m.i < m.f;
  accept m.i * 2 >= 1;
  accept m.f * K > 0.5;
  emit { lo: min(m.i, 2.5), v: vec3(m.i, 0, 1.5), ys: [m.i, 2.5], s: m.i, q: m.i / 2 };
}
)";

std::vector<std::string> body_texts(const model::Body& body) {
  std::vector<std::string> out;
  for (const model::BodyStmt& s : body) out.push_back(model::body_stmt_text(s));
  return out;
}

TEST(LowerBody, EveryPromotionToFloatIsAnExplicitNode) {
  CompiledSpec c = compile_ok(kConversions);
  ASSERT_TRUE(c.ok);
  const model::Connection* conn = find_connection(c.lowered->app, "Dst.cmd", "from_Src_m");
  ASSERT_TRUE(conn && conn->body);
  EXPECT_EQ(body_texts(*conn->body),
            (std::vector<std::string>{
                // A comparison of an int with a float compares floats.
                "(accept 6 (< (float (field i msg)) (field f msg)))",
                // Ints alone stay ints.
                "(accept 7 (>= (* (field i msg) 2) 1))",
                // Float arithmetic converts its int operand, the constant's too.
                "(accept 8 (> (* (field f msg) (float 3)) 0.5))",
                // min of a float, vec3's arguments, list items among floats, a field declared
                // float, and `/`.
                "(emit 9 (record lo (call min (float (field i msg)) 2.5) v (call vec3 (float "
                "(field i msg)) (float 0) 1.5) ys (list (float (field i msg)) 2.5) s (float "
                "(field i msg)) q (/ (float (field i msg)) (float 2))))"}));
  // The constant keeps its name for the Lua, and the conversion its type.
  const model::BodyExpr& k = (*conn->body)[2].expr.args[0].args[1];
  ASSERT_EQ(k.op, model::BodyExpr::Op::ToFloat);
  EXPECT_EQ(k.type->kind, Type::Kind::Float);
  EXPECT_EQ(k.args[0].constant, "K");
  EXPECT_EQ(k.args[0].constant_line, 4);
}

// ---- the IR's types against sema's, on every spec of the repository ------------------------

// Equal types; with `promoted`, b may have a float where a has an int (a list or record
// literal converted to where it is delivered or stored).
bool same(const TypePtr& a, const TypePtr& b, bool promoted = false) {
  if (!a || !b) return !a && !b;
  if (promoted && a->kind == Type::Kind::Int && b->kind == Type::Kind::Float) return true;
  if (a->kind != b->kind) return false;
  if (a->kind == Type::Kind::List) return same(a->element, b->element, promoted);
  if (a->kind != Type::Kind::Record) return true;
  if (a->fields.size() != b->fields.size()) return false;
  for (size_t i = 0; i < a->fields.size(); ++i)
    if (a->fields[i].name != b->fields[i].name ||
        !same(a->fields[i].type, b->fields[i].type, promoted))
      return false;
  return true;
}

std::string text(const TypePtr& t) { return t ? t->to_string() : "null"; }

// Walks a checked expression and its IR together; a ToFloat node stands for an int operand.
// Returns the number of IR nodes compared.
int compare(const ast::Expr& a, const model::BodyExpr& m, const std::string& where) {
  using Kind = ast::Expr::Kind;
  if (m.op == model::BodyExpr::Op::ToFloat) {
    EXPECT_TRUE(a.type && a.type->kind == Type::Kind::Int) << where;
    EXPECT_EQ(text(m.type), "float") << where;
    return 1 + compare(a, m.args[0], where);
  }
  if (a.kind == Kind::Lambda) return compare(*a.args[0], m.args[0], where);
  bool literal = a.kind == Kind::List || a.kind == Kind::Record;
  EXPECT_TRUE(same(a.type, m.type, literal)) << where << ": sema " << text(a.type) << ", IR "
                                             << text(m.type) << " at " << model::body_expr_text(m);
  if (a.kind == Kind::Name || a.kind == Kind::Otherwise) return 1;
  EXPECT_EQ(a.args.size(), m.args.size()) << where;
  int n = 1;
  for (size_t i = 0; i < a.args.size() && i < m.args.size(); ++i)
    n += compare(*a.args[i], m.args[i], where);
  return n;
}

int compare(const ast::Block& a, const std::vector<model::BodyStmt>& m, const std::string& where) {
  EXPECT_EQ(a.size(), m.size()) << where;
  int n = 0;
  for (size_t i = 0; i < a.size() && i < m.size(); ++i) {
    std::string at = where + ":" + std::to_string(m[i].line);
    if (a[i]->expr) n += compare(*a[i]->expr, m[i].expr, at);
    n += compare(a[i]->body, m[i].then_body, at);
    n += compare(a[i]->else_body, m[i].else_body, at);
  }
  return n;
}

// Every body, predicate, assert and resource `when` of `spec` against its lowering.
int compare(const ast::Spec& spec, const LoweredApp& low, const std::string& file) {
  const model::App& app = low.app;
  int n = 0;
  for (const ast::ArbitrateDecl& a : spec.arbitrations)
    for (const ast::Rule& r : a.rules)
      if (const model::Connection* c = find_connection(app, a.port.qualified(), r.name);
          c && c->body)
        n += compare(r.body, *c->body, file + " " + r.name);
  for (const ast::ConnectDecl& d : spec.connects)
    for (const model::Connection& c : app.connections)
      if (c.kind == model::ConnectionKind::Connect && c.source == d.source.qualified() &&
          c.destination == d.destination.qualified() && c.body)
        n += compare(d.body, *c.body, file + " connect");
  for (const MonitorPlan& p : low.monitors)
    for (const DerivedFeed& f : p.derived)
      for (const ast::DerivedEventDecl& d : spec.derived_events)
        if (d.name == f.event) n += compare(*d.predicate, f.predicate, file + " " + d.name);
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    size_t k = 0;  // a port's asserts are lowered in the spec's order
    for (const ast::AssertDecl& as : spec.asserts) {
      if (as.port.qualified() != p.port) continue;
      if (k < p.asserts.size() && as.over_data && p.asserts[k].emitted)
        n += compare(*as.property, *p.asserts[k].emitted, file + " assert");
      ++k;
    }
  }
  for (size_t i = 0; i < spec.resources.size() && i < app.resources.size(); ++i)
    if (spec.resources[i].uses && app.resources[i].uses)
      n += compare(*spec.resources[i].uses, *app.resources[i].uses, file + " resource");
  return n;
}

// The IR read back from app.json has the text and the types it was written with.
void compare_read_back(const model::Body& a, const model::Body& b, const std::string& where);
void compare_read_back(const model::BodyExpr& a, const model::BodyExpr& b,
                       const std::string& where) {
  EXPECT_TRUE(same(a.type, b.type)) << where << " " << model::body_expr_text(a);
  ASSERT_EQ(a.args.size(), b.args.size()) << where;
  for (size_t i = 0; i < a.args.size(); ++i) compare_read_back(a.args[i], b.args[i], where);
}
void compare_read_back(const model::Body& a, const model::Body& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(model::body_stmt_text(a[i]), model::body_stmt_text(b[i])) << where;
    compare_read_back(a[i].expr, b[i].expr, where);
    compare_read_back(a[i].then_body, b[i].then_body, where);
    compare_read_back(a[i].else_body, b[i].else_body, where);
  }
}

TEST(LowerBody, TheIrsTypesAreSemasOnEverySpecAndSurviveAppJson) {
  namespace fs = std::filesystem;
  int specs = 0, nodes = 0;
  for (const char* dir : {"specs", "examples", "tests"}) {
    for (const auto& entry :
         fs::recursive_directory_iterator(arbc::testing::source_dir() + "/" + dir)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".spec") continue;
      std::string path = entry.path().string();
      frontend::CheckResult checked = frontend::check_file(path);
      if (!checked.ok() || !checked.spec) continue;  // specs that show errors
      LowerOptions options;
      options.script_dir = entry.path().parent_path().string();
      std::shared_ptr<const ast::Spec> spec(std::move(checked.spec));
      LowerResult low = lower_spec(spec, options);
      if (!low.ok) continue;
      ++specs;
      nodes += compare(*spec, *low.lowered, path);
      model::App app = low.lowered->app;
      for (model::Connection& c : app.connections)  // what `arbc build` adds, the reader needs
        if (!c.monitor.empty()) c.monitor_sha256 = std::string(64, '0');
      std::string err;
      std::optional<model::App> back = model::from_app_json(model::to_app_json(app), &err);
      ASSERT_TRUE(back) << path << ": " << err;
      for (size_t i = 0; i < back->connections.size(); ++i)
        if (back->connections[i].body)
          compare_read_back(*low.lowered->app.connections[i].body, *back->connections[i].body,
                            path + " " + back->connections[i].name);
    }
  }
  EXPECT_GE(specs, 40);  // the walk found the repository's specs
  EXPECT_GE(nodes, 1000);
}

}  // namespace
}  // namespace arbc::lower
