#include "runtime/event_container.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

namespace arbc {
namespace {

using namespace std::chrono_literals;

TEST(EventContainerTest, PresentIffBeforeExpiry) {
  EventContainer box;
  int e = box.index().intern("e");
  std::vector<Nanos> expired;
  box.on_expiry([&](int, int, Nanos at) { expired.push_back(at); });
  box.set(e, 0, 1500ms);
  EXPECT_TRUE(box.has(e, 1s));
  EXPECT_TRUE(box.has(e, 1500ms - 1ns));  // the last instant before the expiry
  EXPECT_FALSE(box.has(e, 1500ms));
  EXPECT_EQ(expired, std::vector<Nanos>{1500ms});
}

TEST(EventContainerTest, OwnersAreIndependent) {
  EventContainer box;
  int e = box.index().intern("e");
  box.set(e, 0, kNever);
  box.set(e, 1, 2s);
  EXPECT_FALSE(box.unset(e, 2));  // never set by owner 2
  EXPECT_TRUE(box.unset(e, 0));
  EXPECT_TRUE(box.has(e, 1s));   // owner 1's entry holds it
  EXPECT_FALSE(box.has(e, 2s));  // and lapses on time
  box.set(e, 1, 5s);             // refresh after lapse
  EXPECT_TRUE(box.has(e, 4s));
  box.set(e, 1, 4500ms);  // a refresh may shorten the lifetime
  EXPECT_FALSE(box.has(e, 4600ms));
}

// An entry without a lifetime stays whatever the time, even the last instant there is.
TEST(EventContainerTest, AnEntryWithoutALifetimeNeverLapses) {
  EventContainer box;
  int e = box.index().intern("e");
  box.set(e, 0, kNever);
  EXPECT_TRUE(box.has(e, kLongestDuration));
  EXPECT_TRUE(box.has(e, kNever));
}

// The case the old 1 ns tolerance was for: in doubles 0.2 + 0.1 > 0.3, so an event set at
// 0.2 s for 0.1 s was still present at 0.3 s. In nanoseconds it lapses at 0.3 s exactly, as the
// proof's reals say, and the last nanosecond before is still inside it.
TEST(EventContainerTest, AnEntrySetAt200msFor100msIsAbsentAtExactly300ms) {
  EventContainer box;
  int e = box.index().intern("e");
  Nanos set_at = nanos_from_seconds(0.2), lifetime = nanos_from_seconds(0.1);
  box.set(e, 0, set_at + lifetime);
  EXPECT_TRUE(box.has(e, 300ms - 1ns));
  EXPECT_FALSE(box.has(e, nanos_from_seconds(0.1 + 0.2)));  // the double 0.30000000000000004
  EXPECT_FALSE(box.has(e, 300ms));
}

// The presence mask a decision reads agrees with the entries' own expiries, checked the slow
// way, under random sets (with lifetimes or until unset), refreshes, unsets and time steps of
// whole nanoseconds (zero, one, a few, or milliseconds), for events on both sides of the mask's
// inline first word (ids 0..99).
TEST(EventContainerTest, PresenceMaskAgreesWithPerEntryExpiry) {
  EventContainer box;
  for (int i = 0; i < 100; ++i) box.index().intern("e" + std::to_string(i));
  std::map<std::pair<int, int>, Nanos> entries;  // (event, owner) -> expiry
  int lapsed = 0, expected_lapsed = 0;
  box.on_expiry([&](int, int, Nanos) { ++lapsed; });
  std::mt19937 random(3);
  Nanos t{0};
  // A duration of a few nanoseconds or of milliseconds: lapses land on and beside instants.
  auto some_time = [&] {
    auto n = static_cast<int64_t>(random() % 10);
    return random() % 2 ? Nanos(n) : n * 1ms;
  };
  // The model's side of a lapse: every entry whose expiry has come goes, and is counted.
  auto lapse_model = [&] {
    for (auto it = entries.begin(); it != entries.end();) {
      if (t >= it->second) {
        it = entries.erase(it);
        ++expected_lapsed;
      } else {
        ++it;
      }
    }
  };
  for (int step = 0; step < 20000; ++step) {
    int event = static_cast<int>(random() % 100), owner = static_cast<int>(random() % 3);
    switch (random() % 4) {
      case 0:
      case 1: {
        Nanos expiry = random() % 5 == 0 ? kNever : t + some_time() * 5;
        box.set(event, owner, expiry);
        entries[{event, owner}] = expiry;
        break;
      }
      case 2:
        box.present(t);  // the runtime lapses first (unset_event), so the model may drop too
        lapse_model();
        EXPECT_EQ(box.unset(event, owner), entries.erase({event, owner}) == 1);
        break;
      case 3:
        t += some_time();
        break;
    }
    const EventMask& mask = box.present(t);
    lapse_model();
    for (int e = 0; e < 100; ++e) {
      bool present = false;
      for (int o = 0; o < 3; ++o) {
        auto it = entries.find({e, o});
        present |= it != entries.end() && t < it->second;
      }
      ASSERT_EQ(mask.test(e), present) << "step " << step << " event " << e << " t " << t.count();
    }
    ASSERT_EQ(lapsed, expected_lapsed) << "step " << step;
  }
}

}  // namespace
}  // namespace arbc
