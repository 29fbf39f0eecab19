#include "runtime/executor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace arbc {
namespace {

TEST(ExecutorTest, SimulatedRunsInTimeThenPostingOrder) {
  SimulatedExecutor ex;
  std::vector<int> order;
  ex.post(2, [&] { order.push_back(3); });
  ex.post(1, [&] { order.push_back(1); });
  ex.post(1, [&] {
    order.push_back(2);
    ex.post(1, [&] { order.push_back(22); });  // same time, after those already queued
  });
  auto cancelled = ex.post(1.5, [&] { order.push_back(99); });
  ex.post(5, [&] { order.push_back(5); });
  ex.cancel(cancelled);
  ex.run(3);
  EXPECT_EQ(order, (std::vector<int>{1, 2, 22, 3}));
  EXPECT_EQ(ex.now(), 3);
  ex.run(10);
  EXPECT_EQ(order.back(), 5);
}

TEST(ExecutorTest, SimulatedStop) {
  SimulatedExecutor ex;
  int ran = 0;
  ex.post(1, [&] {
    ++ran;
    ex.stop();
  });
  ex.post(2, [&] { ++ran; });
  ex.run(10);
  EXPECT_EQ(ran, 1);
  EXPECT_EQ(ex.now(), 1);
}

TEST(ExecutorTest, RealtimeFollowsTheWallClockAndAcceptsOtherThreads) {
  RealtimeExecutor ex;
  std::vector<double> at;
  std::atomic<int> from_thread{0};
  ex.post(0.05, [&] { at.push_back(ex.now()); });
  std::thread other([&] {
    for (int i = 0; i < 100; ++i) ex.post(ex.now(), [&] { from_thread++; });
  });
  ex.run(0.2);
  other.join();
  ex.run(0.25);  // tasks posted late still run
  ASSERT_EQ(at.size(), 1u);
  EXPECT_GE(at[0], 0.05);
  EXPECT_LT(at[0], 0.15);
  EXPECT_EQ(from_thread.load(), 100);
  EXPECT_GE(ex.now(), 0.25);
}

}  // namespace
}  // namespace arbc
