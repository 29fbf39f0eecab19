#include "runtime/trace_container.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

using namespace std::chrono_literals;
using Events = std::set<std::string>;

TraceRecord event_record(Nanos t, const char* op, const char* event, const char* owner,
                         Nanos expiry = kNever) {
  TraceRecord r;
  r.t = t;
  r.kind = TraceKind::Event;
  r.op = op;
  r.event = event;
  r.owner = owner;
  r.expiry = expiry;
  return r;
}

TEST(TraceContainerTest, AnEventIsPresentWhileAnyOwnerHoldsItAndLapsesExactlyAtItsExpiry) {
  TraceContainer box;
  box.apply(event_record(0s, "set", "e", "a", 500ms));
  box.apply(event_record(0s, "set", "e", "b", 800ms));
  box.apply(event_record(0s, "set", "f", "a"));
  EXPECT_EQ(box.present(100ms), (Events{"e", "f"}));
  EXPECT_EQ(box.present(500ms), (Events{"e", "f"}));  // b still holds it
  EXPECT_EQ(box.present(800ms - 1ns), (Events{"e", "f"}));
  EXPECT_EQ(box.present(800ms), (Events{"f"}));  // the last entry lapsed, to the nanosecond
  box.apply(event_record(900ms, "unset", "f", "a"));
  EXPECT_EQ(box.present(900ms), Events{});
}

// present() keeps its last answer until the next expiry or change: each of these would be
// wrong if the cache outlived what it was computed from.
TEST(TraceContainerTest, TheRememberedAnswerEndsAtTheNextExpiryAndAtEveryChange) {
  TraceContainer box;
  box.apply(event_record(0s, "set", "e", "a", 1s));
  EXPECT_EQ(box.present(0s), Events{"e"});
  EXPECT_EQ(box.present(1s), Events{});              // past the expiry it was valid until
  box.apply(event_record(1s, "set", "e", "a", 2s));  // a refresh of the same entry
  EXPECT_EQ(box.present(1s), Events{"e"});
  box.apply(event_record(1500ms, "set", "g", "b", 3s));
  EXPECT_EQ(box.present(1500ms), (Events{"e", "g"}));
  box.apply(event_record(1600ms, "unset", "e", "a"));
  EXPECT_EQ(box.present(1600ms), Events{"g"});
  box.apply(event_record(1700ms, "expire", "g", "b", 3s));  // late news: changes nothing
  EXPECT_EQ(box.present(2999ms), Events{"g"});
  EXPECT_EQ(box.present(3s), Events{});
}

}  // namespace
}  // namespace arbc
