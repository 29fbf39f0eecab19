// Lists of any length (docs/checks.md#message-data): a body that reads its message's list only
// through `len` and constant indexes below the capacity is encoded exactly for every length
// (EncodedBody::bounded false), so a question about it is answered with lists longer than the
// capacity; a body that reads an element at an index it does not know needs the bound.
#include <gtest/gtest.h>

#include "core/body_text.h"
#include "core/type.h"
#include "verify/body_encoding.h"
#include "verify/lua_number.h"
#include "verify/tail_slots.h"

namespace arbc::verify {
namespace {

constexpr int kCapacity = 4;

struct Encoded {
  z3::context ctx;
  std::vector<z3::expr> domain, within;
  std::optional<SymValue> msg;
  std::optional<EncodedBody> body;
};

// `accept PREDICATE` over a message of type list<{ d: float }> with capacity kCapacity and
// `slots` stand-ins past it (SymValue::tail).
// With `type`, a message of that type (canonical text) instead.
void encode(Encoded& out, const std::string& predicate, int slots = 0,
            const std::string& type = "list<{d: float}>") {
  std::string err;
  std::optional<model::BodyStmt> s = model::parse_body_stmt("(accept 1 " + predicate + ")", &err);
  ASSERT_TRUE(s) << err;
  TypePtr t = parse_type(type, &err);
  ASSERT_TRUE(t) << err;
  out.msg = fresh_value(out.ctx, *t, "m", kCapacity, out.domain, out.within, slots);
  out.body = encode_body(out.ctx, {*s}, *out.msg, "r");
  ASSERT_EQ(out.body->opaque, "");
}

// Whether the body accepts some message with exactly `len` elements (the bound assumed only if
// the encoding says it needs it, as DataQuery asks).
z3::check_result accepts_with_length(Encoded& e, int64_t len) {
  z3::solver s(e.ctx);
  for (const z3::expr& d : e.domain) s.add(d);
  if (e.body->bounded)
    for (const z3::expr& w : e.within) s.add(w);
  for (const z3::expr& x : e.body->side) s.add(x);
  for (const AcceptTracker& t : e.body->trackers) s.add(t.literal);
  s.add(e.body->accepts);
  s.add(e.msg->scalar == lua::int_val(e.ctx, len));
  return s.check();
}

TEST(ListLength, LenAloneIsExactForEveryLength) {
  Encoded e;
  encode(e, "(>= (call len msg) 5)");
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(accepts_with_length(e, 5), z3::sat);  // past the capacity of 4
  EXPECT_EQ(accepts_with_length(e, 1000000), z3::sat);
  EXPECT_EQ(accepts_with_length(e, 4), z3::unsat);
}

TEST(ListLength, ConstantIndexBelowTheCapacityIsExact) {
  Encoded e;
  encode(e, "(and (>= (call len msg) 6) (< (field d (index msg 3)) 1.0))");
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(accepts_with_length(e, 6), z3::sat);
  EXPECT_EQ(accepts_with_length(e, 5), z3::unsat);
}

// Out of range, the generated Lua has no value (the message is dropped `no-value`): the body
// does not accept, whatever the length.
TEST(ListLength, ConstantIndexOutOfRangeHasNoValue) {
  Encoded e;
  encode(e, "(< (field d (index msg 2)) 1.0)");
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(accepts_with_length(e, 2), z3::unsat);
  EXPECT_EQ(accepts_with_length(e, 3), z3::sat);
}

TEST(ListLength, ReadingPastTheCapacityNeedsTheBound) {
  for (const char* p :
       {"(< (field d (index msg 5)) 1.0)", "(< (field d (index msg (- (call len msg) 1))) 1.0)",
        "(< (field d (call min_by msg (lambda o (field d (param o))))) 1.0)", "(== msg msg)",
        "(>= (call len (+ msg msg)) 2)"}) {
    Encoded e;
    encode(e, p);
    EXPECT_TRUE(e.body->bounded) << p;
    EXPECT_EQ(accepts_with_length(e, kCapacity + 1), z3::unsat) << p;
  }
}

const char* kMinBelowZero = "(< (field d (call min_by msg (lambda o (field d (param o))))) 0.0)";
// Every encoded element (the first kCapacity) has d >= 0.
const char* kItemsNotNegative =
    "(and (>= (field d (index msg 0)) 0.0) (and (>= (field d (index msg 1)) 0.0) "
    "(and (>= (field d (index msg 2)) 0.0) (>= (field d (index msg 3)) 0.0))))";

// With stand-ins past the capacity, min_by reads every element of a list of any length: the
// smallest may be the fifth (issue 38: a rule that needs five elements looked dead by data).
TEST(ListLength, MinByReadsPastTheCapacityThroughTheStandIns) {
  Encoded e;
  encode(e, std::string("(and ") + kMinBelowZero + " " + kItemsNotNegative + ")", 1);
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(e.body->tail_reads, 1);
  EXPECT_EQ(accepts_with_length(e, kCapacity), z3::unsat);
  EXPECT_EQ(accepts_with_length(e, kCapacity + 1), z3::sat);
  EXPECT_EQ(accepts_with_length(e, 1000), z3::sat);
}

// Two reads need two stand-ins: the smallest and the largest may both lie past the capacity.
// The witness puts them in order, and the elements past the last repeat it, which changes
// neither choice.
TEST(ListLength, EachScanningReadHasAStandInOfItsOwn) {
  const std::string both =
      std::string("(and ") + kMinBelowZero +
      " (and (> (field d (call max_by msg (lambda o (field d (param o))))) "
      "10.0) " +
      "(and " + kItemsNotNegative +
      " (and (<= (field d (index msg 0)) 10.0) (and (<= (field d (index msg 1)) "
      "10.0) (and (<= (field d (index msg 2)) 10.0) (<= (field d (index msg "
      "3)) 10.0)))))))";
  Encoded e;
  encode(e, both, 2);
  EXPECT_EQ(e.body->tail_reads, 2);
  EXPECT_EQ(accepts_with_length(e, kCapacity + 1), z3::unsat);  // one element cannot be both
  EXPECT_EQ(accepts_with_length(e, kCapacity + 2), z3::sat);
  z3::solver s(e.ctx);
  for (const z3::expr& d : e.domain) s.add(d);
  for (const AcceptTracker& t : e.body->trackers) s.add(t.literal);
  s.add(e.body->accepts);
  s.add(e.msg->scalar == lua::int_val(e.ctx, 9));
  ASSERT_EQ(s.check(), z3::sat);
  Value m = concrete(s.get_model(), *e.msg);
  ASSERT_EQ(m.as_list().size(), 9u);
  double lo = 0, hi = 0;
  for (const Value& o : m.as_list()) {
    lo = std::min(lo, o["d"].as_float());
    hi = std::max(hi, o["d"].as_float());
  }
  EXPECT_LT(lo, 0.0);
  EXPECT_GT(hi, 10.0);
}

// The scanning reads of a source's rules size its stand-ins; a read inside a lambda runs once
// per element and is not counted.
TEST(ListLength, ScanningReadsAreCountedOutsideLambdas) {
  std::string err;
  std::optional<model::BodyStmt> s = model::parse_body_stmt(
      "(accept 1 (< (call min (call max_by msg (lambda o (call min (field d (param o)) "
      "(call max msg))))) 0.0))",
      &err);
  ASSERT_TRUE(s) << err;
  EXPECT_EQ(scanning_reads({*s}), 2);  // min of one argument and max_by; not the max inside
}

// A list literal has a known length: indexing it at an unknown index is exact.
TEST(ListLength, LiteralListsNeedNoBound) {
  Encoded e;
  encode(e, "(== (index (list 1 2 3) (- (call len msg) 7)) 2)");
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(accepts_with_length(e, 8), z3::sat);
  EXPECT_EQ(accepts_with_length(e, 7), z3::unsat);
}

// T[N]: every element is encoded, past the capacity too, and the length is N: reading any
// index is exact and needs no bound (the runtime checks each value has N elements).
TEST(ListLength, FixedListsAreWholeAtAnySize) {
  for (const char* p :
       {"(< (field d (index msg 5)) 1.0)", "(< (field d (index msg (- (call len msg) 1))) 1.0)",
        "(< (field d (call min_by msg (lambda o (field d (param o))))) 1.0)"}) {
    Encoded e;
    encode(e, p, 0, "{d: float}[6]");
    EXPECT_FALSE(e.body->bounded) << p;
    EXPECT_EQ(e.msg->items.size(), 6u) << p;
    EXPECT_EQ(accepts_with_length(e, 6), z3::sat) << p;
    EXPECT_EQ(accepts_with_length(e, 5), z3::unsat) << p;  // no value of the type has 5
  }
  // The smallest may be the sixth, beyond the capacity of 4, with no stand-in.
  Encoded e;
  encode(e, std::string("(and ") + kMinBelowZero + " " + kItemsNotNegative + ")", 0,
         "{d: float}[6]");
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(accepts_with_length(e, 6), z3::sat);
}

// list<T, N>: at most N elements, whatever the body reads; no value has more.
TEST(ListLength, BoundedListsHaveNoLongerValue) {
  Encoded e;
  encode(e, "(>= (call len msg) 2)", 0, "list<{d: float}, 3>");
  EXPECT_FALSE(e.body->bounded);
  EXPECT_EQ(accepts_with_length(e, 3), z3::sat);
  EXPECT_EQ(accepts_with_length(e, 4), z3::unsat);
}

// string<N>: at most N bytes; no value is longer, whatever the body compares it with.
TEST(ListLength, BoundedStringsHaveNoLongerValue) {
  for (auto [text, fits] : {std::pair{"abc", true}, std::pair{"abcd", false}}) {
    Encoded e;
    encode(e, std::string("(== msg \"") + text + "\")", 0, "string<3>");
    z3::solver s(e.ctx);
    for (const z3::expr& d : e.domain) s.add(d);
    for (const z3::expr& x : e.body->side) s.add(x);
    for (const AcceptTracker& t : e.body->trackers) s.add(t.literal);
    s.add(e.body->accepts);
    EXPECT_EQ(s.check(), fits ? z3::sat : z3::unsat) << text;
  }
}

}  // namespace
}  // namespace arbc::verify
