// The text form of bodies in app.json (core/body_text.h): round trips and malformed input.
#include "core/body_text.h"

#include <gtest/gtest.h>

namespace arbc::model {
namespace {

TEST(BodyText, StatementsRoundTrip) {
  const char* texts[] = {
      "(accept 33 (<= (field dist (local obj)) 0.4))",
      "(let 32 obj (call min_by msg (lambda o (field dist (param o)))))",
      ("(if 44 (<= (field dist (local obj)) 0.4) ((emit 44 (record pos (field pos (local obj)) "
       "verb \"cancel\"))) ((emit 45 (record verb \"pull\"))))"),
      "(var 3 n 0)",
      "(assign 4 n (+ (local n) 1))",
      "(every 5 ((set 5 e_x) (unset 6 e_y)))",
      "(set 9 e_face 1.5)",
      "(throttle 7)",
      "(emit 8 (list 1 2.5 -3 \"a\\\"b\" true false (neg (index msg 0)) (not true)))",
  };
  for (const char* t : texts) {
    std::string err;
    std::optional<BodyStmt> s = parse_body_stmt(t, &err);
    ASSERT_TRUE(s) << t << ": " << err;
    EXPECT_EQ(body_stmt_text(*s), t);
  }
}

TEST(BodyText, IntAndFloatLiteralsStayApart) {
  std::string err;
  std::optional<BodyExpr> i = parse_body_expr("3", &err);
  std::optional<BodyExpr> f = parse_body_expr("3.0", &err);
  ASSERT_TRUE(i && f);
  EXPECT_EQ(i->op, BodyExpr::Op::Int);
  EXPECT_EQ(f->op, BodyExpr::Op::Float);
  EXPECT_EQ(body_expr_text(*f), "3.0");
}

TEST(BodyText, MalformedTextIsAnErrorWithAnOffset) {
  const char* bad[] = {"(accept)",
                       "(accept x (> msg 1))",
                       "(frobnicate 1 msg)",
                       "(emit 1 (+ 1))",
                       "(emit 1 (call len msg)",
                       "(let 1 x msg) trailing",
                       "(if 1 true (emit 1 2))"};
  for (const char* t : bad) {
    std::string err;
    EXPECT_FALSE(parse_body_stmt(t, &err)) << t;
    EXPECT_NE(err.find("offset"), std::string::npos) << t << ": " << err;
  }
}

TEST(BodyText, DeepNestingIsRefusedNotACrash) {
  std::string t = "(emit 1 ";
  for (int i = 0; i < 100000; ++i) t += "(not ";
  std::string err;
  EXPECT_FALSE(parse_body_stmt(t, &err));
  EXPECT_NE(err.find("nested too deeply"), std::string::npos) << err;
}

}  // namespace
}  // namespace arbc::model
