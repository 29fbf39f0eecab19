// Stamps in a test's messages (docs/testing.md#stamps). Where a message carries a stamp (a
// record with integer `sec` and `nanosec`, type_rules.h is_stamp: builtin_interfaces/msg/Time),
// a test may write it as an instant of the run instead of two integers:
//   now()          the step's instant, as a monitor's now() reads it when the message arrives
//   now() - 150ms  150 ms before it (a message 150 ms old on arrival); now() + D after it
//   900ms          an instant counted from the start of the run
// Sema replaces each by the record `{sec: S, nanosec: N}` (nanosec in [0, 1e9), sec rounded
// down, as ROS 2 normalises a Time) before the value is typed, so that the rest of the test
// machinery (the fit to the port, the literal value, lowering) sees an ordinary literal and the
// runtime receives exactly what a publisher stamping at that instant would send.
#include <optional>

#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/type_rules.h"

namespace arbc::frontend {

using namespace ast;

namespace {

bool is_now(const Expr& e) {
  return e.kind == Expr::Kind::Call && e.text == "now" && e.args.empty();
}

bool mentions_now(const Expr& e) {
  if (is_now(e)) return true;
  for (const ExprPtr& a : e.args)
    if (a && mentions_now(*a)) return true;
  return false;
}

ExprPtr integer_literal(int64_t v, const Loc& loc) {
  auto e = std::make_unique<Expr>();
  e->kind = Expr::Kind::Number;
  e->is_int = true;
  e->integer = v;
  e->number = static_cast<double>(v);
  e->text = std::to_string(v);
  e->loc = loc;
  return e;
}

// `e` becomes `{sec: S, nanosec: N}` for the instant `t` (whole nanoseconds from the start).
void become_stamp(Expr& e, Nanos t) {
  constexpr int64_t kPerSecond = 1'000'000'000;
  int64_t ns = t.count();
  int64_t sec = ns / kPerSecond - (ns % kPerSecond < 0 ? 1 : 0);
  Loc loc = e.loc;
  Expr stamp;
  stamp.kind = Expr::Kind::Record;
  stamp.loc = loc;
  stamp.names = {{"sec", loc}, {"nanosec", loc}};
  stamp.args.push_back(integer_literal(sec, loc));
  stamp.args.push_back(integer_literal(ns - sec * kPerSecond, loc));
  e = std::move(stamp);
}

constexpr const char* kStampForms =
    "write now() (the step's instant), now() - D, now() + D, a duration from the start such as "
    "900ms, or the record {sec: S, nanosec: N}";

}  // namespace

// The instant a stamp written as `now()`, `now() - D1 + D2 ...` or a time from the start
// stands for; nullopt when it is written otherwise (`*reported`: and that was said).
std::optional<Nanos> Sema::stamp_instant(Expr& e, std::optional<Nanos> at, bool* reported) {
  Scope empty;
  if (!at && mentions_now(e)) {
    error(e.loc,
          "now() is the instant of a test input's step; in an expected value write the stamp as a "
          "time from the start (such as 900ms) or as the record {sec: S, nanosec: N}",
          diag::TestValue);
    *reported = true;
    return std::nullopt;
  }
  if (is_now(e)) return at;
  if (e.kind == Expr::Kind::Binary && (e.op == "+" || e.op == "-") && mentions_now(*e.args[0]) &&
      !mentions_now(*e.args[1])) {
    std::optional<Nanos> base = stamp_instant(*e.args[0], at, reported);
    if (!base) return std::nullopt;
    Expr& d = *e.args[1];
    check_expr(d, empty);
    if (d.type && !d.is_duration && d.kind != Expr::Kind::Duration)
      error(d.loc, "the offset of a stamp from now() must be a time such as 150ms",
            diag::TestValue);
    std::optional<Nanos> n = d.type && (d.is_duration || d.kind == Expr::Kind::Duration)
                                 ? duration_nanos(d, "the offset of a stamp from now()")
                                 : std::nullopt;
    *reported = !n;
    if (!n) return std::nullopt;
    return e.op == "+" ? *base + *n : *base - *n;
  }
  if (mentions_now(e)) {
    error(e.loc, std::string("a stamp cannot be computed this way: ") + kStampForms,
          diag::TestValue);
    *reported = true;
    return std::nullopt;
  }
  if (e.kind != Expr::Kind::Duration && e.kind != Expr::Kind::Name) return std::nullopt;
  check_expr(e, empty);
  *reported = !e.type;  // an unknown name, said once (the value is not checked again)
  if (!e.type || !(e.is_duration || e.kind == Expr::Kind::Duration))
    return std::nullopt;  // not a time: the fit to the port reports it
  std::optional<Nanos> n = duration_nanos(e, "a stamp given as a time from the start");
  *reported = !n;
  return n;
}

bool Sema::desugar_test_stamps(Expr& e, const TypePtr& want, std::optional<Nanos> at) {
  if (!want) return true;
  if (is_stamp(want) && e.kind != Expr::Kind::Record) {
    bool reported = false;
    std::optional<Nanos> t = stamp_instant(e, at, &reported);
    if (t) become_stamp(e, *t);
    return !reported;
  }
  bool ok = true;
  if (e.kind == Expr::Kind::Record && want->kind == Type::Kind::Record) {
    for (size_t i = 0; i < e.args.size(); ++i) {
      const Field* f = want->field(e.names[i].name);
      ok = desugar_test_stamps(*e.args[i], f ? f->type : nullptr, at) && ok;
    }
  } else if (e.kind == Expr::Kind::List && want->kind == Type::Kind::List) {
    for (const ExprPtr& item : e.args) ok = desugar_test_stamps(*item, want->element, at) && ok;
  } else if (mentions_now(e)) {
    error(e.loc,
          "now() in a test's message stands for the step's instant, and is written only where "
          "a stamp (a record of sec and nanosec, such as builtin_interfaces/msg/Time) is "
          "expected; this value is a " +
              describe(want),
          diag::TestValue);
    return false;
  }
  return ok;
}

}  // namespace arbc::frontend
