// Instructions per message, a figure the other jobs on the shared machine cannot disturb: the
// window of messages the benchmarks of bench/runtime and bench/dds count under callgrind
// (bench/callgrind_window.sh reads the dump).
#pragma once

#include <cstdint>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(name) (void)(name)
#endif

namespace arbc::bench {

// Run under `valgrind --tool=callgrind --collect-atstart=yes`, the first run of a benchmark that
// reaches kWarmup + kCounted iterations zeroes the counts after kWarmup messages (the runtime
// or state is built, caches and the collector have settled) and dumps them after kCounted
// more: the dump holds those messages and nothing else. Natively the client requests are a
// few no-op instructions, twice per benchmark run.
// A message that costs milliseconds (a LaserScan) gets a smaller window: `counted` is what the
// dump is divided by (callgrind_window's COUNT).
class InstructionWindow {
 public:
  static constexpr uint64_t kWarmup = 2000;
  static constexpr uint64_t kCounted = 10000;
  explicit InstructionWindow(const char* name, uint64_t warmup = kWarmup,
                             uint64_t counted = kCounted)
      : name_(name), warmup_(warmup), counted_(counted) {}
  void after(uint64_t messages) {
    if (done_) return;
    if (messages == warmup_) {
      CALLGRIND_ZERO_STATS;
    } else if (messages == warmup_ + counted_) {
      CALLGRIND_DUMP_STATS_AT(name_);
      done_ = true;
    }
  }

 private:
  const char* name_;
  uint64_t warmup_, counted_;
  bool done_ = false;
};

}  // namespace arbc::bench
