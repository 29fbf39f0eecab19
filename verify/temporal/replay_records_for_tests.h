// Replay records written in seconds, for the judge's tests (judge_test.cc, response_test.cc):
// times to the nanosecond (core/instant.h); an expiry below 0 is none.
#pragma once

#include <string>

#include "verify/temporal/judge.h"

namespace arbc::verify::temporal::records {

inline Nanos at(double t) { return nanos_from_seconds(t); }
inline Nanos until(double t) { return t < 0 ? kNever : nanos_from_seconds(t); }
inline ReplayRecord record(ReplayRecord::Kind k, double t, const std::string& owner,
                           const std::string& event = "", double expiry = -1) {
  return {k, at(t), owner, event, until(expiry)};
}
inline ReplayRecord deliver(double t, const std::string& rule) {
  return record(ReplayRecord::Kind::Deliver, t, rule);
}
inline ReplayRecord drop(double t, const std::string& rule) {
  return record(ReplayRecord::Kind::Drop, t, rule);
}
inline ReplayRecord set(double t, const std::string& owner, const std::string& e, double expiry) {
  return record(ReplayRecord::Kind::Set, t, owner, e, expiry);
}
inline ReplayRecord remove(double t, const std::string& owner, const std::string& e,
                           double expiry) {
  return record(ReplayRecord::Kind::Remove, t, owner, e, expiry);
}

}  // namespace arbc::verify::temporal::records
