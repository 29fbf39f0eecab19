#include "runtime/event_container.h"

#include <gtest/gtest.h>

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
