#include "runtime/event_container.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

namespace arbc {
namespace {

TEST(EventContainerTest, PresentIffBeforeExpiry) {
  EventContainer box;
  int e = box.index().intern("e");
  std::vector<double> expired;
  box.on_expiry([&](int, int, double at) { expired.push_back(at); });
  box.set(e, 0, 1.5);
  EXPECT_TRUE(box.has(e, 1.0));
  EXPECT_TRUE(box.has(e, 1.4999999));
  EXPECT_FALSE(box.has(e, 1.5));
  EXPECT_EQ(expired, std::vector<double>{1.5});
}

TEST(EventContainerTest, OwnersAreIndependent) {
  EventContainer box;
  int e = box.index().intern("e");
  box.set(e, 0, kNever);
  box.set(e, 1, 2.0);
  EXPECT_FALSE(box.unset(e, 2));  // never set by owner 2
  EXPECT_TRUE(box.unset(e, 0));
  EXPECT_TRUE(box.has(e, 1.0));   // owner 1's entry holds it
  EXPECT_FALSE(box.has(e, 2.0));  // and lapses on time
  box.set(e, 1, 5.0);             // refresh after lapse
  EXPECT_TRUE(box.has(e, 4.0));
  box.set(e, 1, 4.5);  // a refresh may shorten the lifetime
  EXPECT_FALSE(box.has(e, 4.6));
}

}  // namespace
}  // namespace arbc

namespace arbc {
namespace {

// The presence mask a decision reads agrees with the entries' own expiries, checked the slow
// way, under random sets (with lifetimes or until unset), refreshes, unsets and time steps, for
// events on both sides of the mask's inline first word (ids 0..99).
// In doubles 0.2 + 0.1 > 0.3; the proof's reals say the entry lapses at 0.3 s, and so must
// the runtime (core/instant.h).
TEST(EventContainerTest, AnEntryLapsesAtItsExpiryDespiteRounding) {
  EventContainer box;
  int e = box.index().intern("e");
  double set_at = 0.2, lifetime = 0.1;
  box.set(e, 0, set_at + lifetime);
  EXPECT_TRUE(box.has(e, 0.29));
  EXPECT_FALSE(box.has(e, 0.3));
}

TEST(EventContainerTest, PresenceMaskAgreesWithPerEntryExpiry) {
  EventContainer box;
  for (int i = 0; i < 100; ++i) box.index().intern("e" + std::to_string(i));
  std::map<std::pair<int, int>, double> entries;  // (event, owner) -> expiry
  int lapsed = 0, expected_lapsed = 0;
  box.on_expiry([&](int, int, double) { ++lapsed; });
  std::mt19937 random(3);
  double t = 0;
  // The model's side of a lapse: every entry whose expiry has come goes, and is counted.
  // (`t` is a sum of steps in doubles, so "has come" is core/instant.h's `reached`.)
  auto lapse_model = [&] {
    for (auto it = entries.begin(); it != entries.end();) {
      if (reached(t, it->second)) {
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
        double expiry = random() % 5 == 0 ? kNever : t + 0.001 * static_cast<double>(random() % 50);
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
        t += 0.001 * static_cast<double>(random() % 10);
        break;
    }
    const EventMask& mask = box.present(t);
    lapse_model();
    for (int e = 0; e < 100; ++e) {
      bool present = false;
      for (int o = 0; o < 3; ++o) {
        auto it = entries.find({e, o});
        present |= it != entries.end() && !reached(t, it->second);
      }
      ASSERT_EQ(mask.test(e), present) << "step " << step << " event " << e << " t " << t;
    }
    ASSERT_EQ(lapsed, expected_lapsed) << "step " << step;
  }
}

}  // namespace
}  // namespace arbc
