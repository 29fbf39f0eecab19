#include "verify/tail_slots.h"

#include <algorithm>

namespace arbc::verify {

namespace {

using model::BodyExpr;
using model::BodyStmt;

bool scans(const BodyExpr& e) {
  if (e.op != BodyExpr::Op::Call) return false;
  if (e.builtin == Builtin::MinBy || e.builtin == Builtin::MaxBy) return true;
  return (e.builtin == Builtin::Min || e.builtin == Builtin::Max) && e.args.size() == 1;
}

int reads_in(const BodyExpr& e) {
  if (e.op == BodyExpr::Op::Lambda) return 0;  // runs per element: not counted (see header)
  int n = scans(e) ? 1 : 0;
  for (const BodyExpr& a : e.args) n += reads_in(a);
  return n;
}

int reads_in(const std::vector<BodyStmt>& block) {
  int n = 0;
  for (const BodyStmt& s : block)
    n += reads_in(s.expr) + reads_in(s.then_body) + reads_in(s.else_body);
  return n;
}

}  // namespace

int scanning_reads(const model::Body& body) { return reads_in(body); }

int tail_slots(const model::App& app, const std::string& source) {
  int n = 0;
  for (const model::Connection& c : app.connections)
    if (c.source == source && c.body && !c.opaque) n += scanning_reads(*c.body);
  return std::min(n, kMaxTailSlots);
}

}  // namespace arbc::verify
