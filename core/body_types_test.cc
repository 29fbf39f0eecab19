// The typing of bodies (core/body_types.h) and the table of builtins (core/builtins.h).
#include "core/body_types.h"

#include <gtest/gtest.h>

#include "core/body_text.h"

namespace arbc::model {
namespace {

BodyStmt stmt(const std::string& text) {
  std::string err;
  std::optional<BodyStmt> s = parse_body_stmt(text, &err);
  EXPECT_TRUE(s) << text << ": " << err;
  return s ? *s : BodyStmt{};
}

std::string type_text(const TypePtr& t) { return t ? t->to_string() : "null"; }

const TypePtr kObjects = parse_type("list<{dist: float, pos: vec3, n: int}>");

TEST(BodyTypes, EveryNodeGetsTheCheckersType) {
  Body body = {stmt("(let 1 obj (call min_by msg (lambda o (field dist (param o)))))"),
               stmt("(accept 2 (<= (field dist (local obj)) 0.4))"),
               stmt("(let 3 k (call min (float (field n (local obj))) 2.5))"),
               stmt("(let 4 v (* (field pos (local obj)) (float 2)))"),
               stmt("(emit 5 (record m (local k) c (call len msg) w (/ (float 1) (float 2))))")};
  ASSERT_TRUE(type_body(body, kObjects));
  EXPECT_EQ(type_text(body[0].expr.type), "{dist: float, pos: vec3, n: int}");
  // The lambda has no value type; its body is typed with the parameter bound to an element.
  EXPECT_EQ(body[0].expr.args[1].type, nullptr);
  EXPECT_EQ(type_text(body[0].expr.args[1].args[0].type), "float");
  EXPECT_EQ(type_text(body[1].expr.type), "bool");
  EXPECT_EQ(type_text(body[2].expr.type), "float");
  EXPECT_EQ(type_text(body[2].expr.args[0].args[0].type), "int");  // under the conversion
  EXPECT_EQ(type_text(body[3].expr.type), "vec3");
  EXPECT_EQ(type_text(body[4].expr.type), "{m: float, c: int, w: float}");
}

TEST(BodyTypes, IntsStayIntsWithoutAConversion) {
  Body body = {
      stmt("(let 1 a (+ (call len msg) 1))"),       stmt("(let 2 b (call max (local a) 3))"),
      stmt("(let 3 c (call abs (neg (local b))))"), stmt("(let 4 d (% (local c) 2))"),
      stmt("(let 5 e (list 1 (local d)))"),         stmt("(let 6 f (list (float 1) 2.5))")};
  ASSERT_TRUE(type_body(body, kObjects));
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(type_text(body[i].expr.type), "int") << i;
  EXPECT_EQ(type_text(body[4].expr.type), "list<int>");
  EXPECT_EQ(type_text(body[5].expr.type), "list<float>");
}

TEST(BodyTypes, ABranchsLocalsEndWithIt) {
  Body body = {stmt("(if 1 true ((let 2 x 1) (emit 3 (local x))) ((emit 4 (local x))))")};
  EXPECT_FALSE(type_body(body, kObjects));  // x of the else branch is the then branch's
  EXPECT_EQ(type_text(body[0].then_body[1].expr.type), "int");
  EXPECT_EQ(body[0].else_body[0].expr.type, nullptr);
}

TEST(BodyTypes, WhatCannotBeTypedIsSaidNotGuessed) {
  for (const char* text : {"(accept 1 (> (field nope msg) 1))", "(emit 1 (local undefined))",
                           "(emit 1 (index (call len msg) 0))"}) {
    Body body = {stmt(text)};
    EXPECT_FALSE(type_body(body, kObjects)) << text;
  }
}

TEST(BodyTypes, TheConversionNodeRoundTripsAsText) {
  std::string err;
  std::optional<BodyExpr> e = parse_body_expr("(call min (float (local i)) 2.5)", &err);
  ASSERT_TRUE(e) << err;
  EXPECT_EQ(e->args[0].op, BodyExpr::Op::ToFloat);
  EXPECT_EQ(body_expr_text(*e), "(call min (float (local i)) 2.5)");
  EXPECT_FALSE(parse_body_expr("(float 1 2)", &err));
  EXPECT_NE(err.find("wrong number of operands of 'float'"), std::string::npos) << err;
}

TEST(Builtins, ACallReadFromTextKnowsItsBuiltin) {
  std::string err;
  std::optional<BodyExpr> len = parse_body_expr("(call len msg)", &err);
  std::optional<BodyExpr> other = parse_body_expr("(call frobnicate msg)", &err);
  ASSERT_TRUE(len && other);
  EXPECT_EQ(len->builtin, Builtin::Len);
  EXPECT_EQ(other->builtin, Builtin::None);  // the proof calls it opaque
}

TEST(Builtins, TheTableIsConsistent) {
  std::string names;
  for (const BuiltinInfo& b : kBuiltins) {
    EXPECT_EQ(find_builtin(b.name), &b);
    EXPECT_EQ(builtin_info(b.id), &b);
    EXPECT_NE(b.id, Builtin::None);
    EXPECT_EQ(b.signature.substr(0, b.name.size() + 1), std::string(b.name) + "(") << b.name;
    EXPECT_FALSE(b.summary.empty()) << b.name;
    EXPECT_FALSE(b.lua_helper.empty()) << b.name;
    EXPECT_TRUE(b.max_args < 0 || b.max_args >= b.min_args) << b.name;
  }
  EXPECT_EQ(find_builtin("length"), nullptr);
  EXPECT_EQ(builtin_info(Builtin::None), nullptr);
  EXPECT_EQ(builtin_names_text(), "len, min_by, max_by, dist, norm, abs, min, max, now, age, vec3");
}

}  // namespace
}  // namespace arbc::model
