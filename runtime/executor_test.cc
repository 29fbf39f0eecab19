#include "runtime/executor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <deque>
#include <map>
#include <random>
#include <vector>

namespace arbc {

using namespace std::chrono_literals;
namespace {

TEST(ExecutorTest, SimulatedRunsInTimeThenPostingOrder) {
  SimulatedExecutor ex;
  std::vector<int> order;
  ex.post(2s, [&] { order.push_back(3); });
  ex.post(1s, [&] { order.push_back(1); });
  ex.post(1s, [&] {
    order.push_back(2);
    ex.post(1s, [&] { order.push_back(22); });  // same time, after those already queued
  });
  auto cancelled = ex.post(1500ms, [&] { order.push_back(99); });
  ex.post(5s, [&] { order.push_back(5); });
  ex.cancel(cancelled);
  ex.run(3s);
  EXPECT_EQ(order, (std::vector<int>{1, 2, 22, 3}));
  EXPECT_EQ(ex.now(), 3s);
  ex.run(10s);
  EXPECT_EQ(order.back(), 5);
}

// What a plain task (TaskQueue::push_plain) of the test below runs: *ran = number.
struct PlainArgument {
  int* ran;
  int number;
};
void run_plain(void* argument) {
  auto* a = static_cast<PlainArgument*>(argument);
  *a->ran = a->number;
}

// The queue with reused slots behaves as the ordered map it replaced: tasks come out in
// (time, posting order), plain tasks among the others, a cancelled task never runs, a stale id
// (a task that ran or was cancelled, its slot since reused) cancels nothing, and cancelled
// entries do not pile up. `next_at` draws each posted task's time.
template <class NextTime>
void expect_queue_agrees_with_an_ordered_map(NextTime next_at) {
  TaskQueue queue;
  std::deque<PlainArgument> plain_arguments;  // a deque: their addresses stay put
  // (time, posting order) -> (task number, id)
  std::map<std::pair<Nanos, uint64_t>, std::pair<int, TaskQueue::TaskId>> model;
  std::map<TaskQueue::TaskId, std::pair<Nanos, uint64_t>> pending;
  std::vector<TaskQueue::TaskId> old_ids;
  std::mt19937 random(11);
  uint64_t posted = 0;
  int ran = -1;
  for (int step = 0; step < 20000; ++step) {
    unsigned what = random() % 10;
    if (what < 2) {  // a plain task: no id, never cancelled
      Nanos at = next_at(random);
      int number = static_cast<int>(posted);
      plain_arguments.push_back({&ran, number});
      queue.push_plain(at, run_plain, &plain_arguments.back());
      model[{at, posted}] = {number, 0};
      ++posted;
    } else if (what < 5) {
      Nanos at = next_at(random);
      int number = static_cast<int>(posted);
      TaskQueue::TaskId id = queue.push(at, [&ran, number] { ran = number; });
      ASSERT_NE(id, 0u);
      model[{at, posted}] = {number, id};
      pending[id] = {at, posted};
      old_ids.push_back(id);
      ++posted;
    } else if (what < 7 && !old_ids.empty()) {
      TaskQueue::TaskId id = old_ids[random() % old_ids.size()];  // pending, ran or cancelled
      queue.cancel(id);
      auto it = pending.find(id);
      if (it != pending.end()) {
        model.erase(it->second);
        pending.erase(it);
      }
    } else if (!model.empty()) {
      ASSERT_FALSE(queue.empty());
      ASSERT_EQ(queue.next_time(), model.begin()->first.first);
      queue.pop()();
      ASSERT_EQ(ran, model.begin()->second.first) << "step " << step;
      pending.erase(model.begin()->second.second);
      model.erase(model.begin());
    }
    ASSERT_EQ(queue.empty(), model.empty());
    ASSERT_EQ(queue.size(), model.size());
    ASSERT_LE(queue.entries(), 2 * model.size() + 17) << "cancelled entries pile up";
  }
}

// Times in any order: most tasks go through the heap. Nanoseconds apart, so that tasks a
// nanosecond apart keep their time order and equal ones their posting order.
TEST(ExecutorTest, TaskQueueAgreesWithAnOrderedMap) {
  expect_queue_agrees_with_an_ordered_map(
      [](std::mt19937& random) { return Nanos(static_cast<int64_t>(random() % 50)); });
}

// Times mostly in order, as the message path posts them (often equal), with one in eight
// earlier than the latest: equal times keep their posting order.
TEST(ExecutorTest, TaskQueueAgreesWithAnOrderedMapWhenPostedInTimeOrder) {
  Nanos latest{0};
  expect_queue_agrees_with_an_ordered_map([&latest](std::mt19937& random) {
    unsigned draw = random() % 8;
    if (draw == 0) return std::max(Nanos(0), latest - Nanos(static_cast<int64_t>(random() % 5)));
    if (draw < 4) latest += 1ns;
    return latest;
  });
}

// A timer re-posted and cancelled over and over (a trig interval being reset) keeps the queue
// small.
TEST(ExecutorTest, RepostedAndCancelledTasksKeepTheQueueSmall) {
  SimulatedExecutor ex;
  int ran = 0;
  ex.post(1000000000s, [&] { ++ran; });
  Executor::TaskId id = 0;
  for (int i = 0; i < 100000; ++i) {
    if (id) ex.cancel(id);
    id = ex.post(1000s + i * 1s, [&] { ran += 100; });
  }
  ex.run(1000000s);
  EXPECT_EQ(ran, 100);  // only the last re-posted one
  ex.run(2000000000s);
  EXPECT_EQ(ran, 101);
}

TEST(ExecutorTest, SimulatedStop) {
  SimulatedExecutor ex;
  int ran = 0;
  ex.post(1s, [&] {
    ++ran;
    ex.stop();
  });
  ex.post(2s, [&] { ++ran; });
  ex.run(10s);
  EXPECT_EQ(ran, 1);
  EXPECT_EQ(ex.now(), 1s);
}

TEST(ExecutorTest, RealtimeFollowsTheWallClockAndAcceptsOtherThreads) {
  RealtimeExecutor ex;
  std::vector<Nanos> at;
  std::atomic<int> from_thread{0};
  ex.post(50ms, [&] { at.push_back(ex.now()); });
  std::thread other([&] {
    for (int i = 0; i < 100; ++i) ex.post(ex.now(), [&] { from_thread++; });
  });
  ex.run(200ms);
  other.join();
  ex.run(250ms);  // tasks posted late still run
  ASSERT_EQ(at.size(), 1u);
  EXPECT_GE(at[0], 50ms);
  EXPECT_LT(at[0], 150ms);
  EXPECT_EQ(from_thread.load(), 100);
  EXPECT_GE(ex.now(), 250ms);
}

}  // namespace
}  // namespace arbc
