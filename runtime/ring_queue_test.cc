#include "runtime/ring_queue.h"

#include <gtest/gtest.h>

#include <deque>
#include <memory>
#include <random>

namespace arbc {
namespace {

// Pushes and pops in random runs, across growth and wrap-around: the same order as a deque.
TEST(RingQueueTest, KeepsFirstInFirstOutOrderAsItGrowsAndWraps) {
  RingQueue<int> ring;
  std::deque<int> model;
  std::mt19937 random(5);
  int next = 0;
  for (int step = 0; step < 20000; ++step) {
    if (random() % 100 < 55) {
      ring.push_back(next);
      model.push_back(next);
      ++next;
    } else if (!model.empty()) {
      ASSERT_EQ(ring.front(), model.front()) << "step " << step;
      ASSERT_EQ(ring.take_front(), model.front()) << "step " << step;
      model.pop_front();
    }
    ASSERT_EQ(ring.size(), model.size());
    ASSERT_EQ(ring.empty(), model.empty());
  }
}

// A taken message's memory goes with it, not when its slot is reused.
TEST(RingQueueTest, TakeFrontLeavesNothingBehind) {
  RingQueue<std::shared_ptr<int>> ring;
  auto value = std::make_shared<int>(7);
  std::weak_ptr<int> watch = value;
  ring.push_back(std::move(value));
  ring.push_back(std::make_shared<int>(8));
  ring.take_front();
  EXPECT_TRUE(watch.expired());
  EXPECT_EQ(*ring.front(), 8);
}

}  // namespace
}  // namespace arbc
