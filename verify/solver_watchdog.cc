#include "verify/solver_watchdog.h"

#include <map>
#include <utility>

namespace arbc::verify {

namespace {

// The queries in flight in this process, under one lock with the watchdogs' interrupts, so an
// interrupt is issued only between a query's start and its end.
std::mutex g_flight_mutex;
std::map<Z3_context, int> g_in_flight;  // queries in flight, per context

// Interrupts `ctx` if a query is in flight; whether it did.
bool interrupt_query(z3::context& ctx) {
  std::lock_guard<std::mutex> lock(g_flight_mutex);
  auto it = g_in_flight.find(ctx);
  if (it == g_in_flight.end() || it->second == 0) return false;
  ctx.interrupt();
  return true;
}

}  // namespace

QueryInFlight::QueryInFlight(z3::context& ctx) : ctx_(ctx) {
  std::lock_guard<std::mutex> lock(g_flight_mutex);
  ++g_in_flight[ctx_];
}

QueryInFlight::~QueryInFlight() {
  std::lock_guard<std::mutex> lock(g_flight_mutex);
  if (--g_in_flight[ctx_] == 0) g_in_flight.erase(ctx_);
}

SolverWatchdog::SolverWatchdog(z3::context& ctx, Clock::time_point deadline,
                               std::function<void()> on_stuck, Clock::duration grace)
    : contexts_{&ctx},
      deadline_(deadline),
      on_stuck_(std::move(on_stuck)),
      grace_(grace),
      thread_([this] { watch(); }) {}

SolverWatchdog::~SolverWatchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void SolverWatchdog::watch_also(z3::context& other) {
  std::lock_guard<std::mutex> lock(mutex_);
  contexts_.push_back(&other);
}

bool SolverWatchdog::fired() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return fired_;
}

void SolverWatchdog::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_until(lock, deadline_, [this] { return stop_; })) return;
  // An interrupt reaches only the query in flight, so it is repeated: a query that started
  // just before the deadline (SolverTimeout::arm let it) is stopped by the next one.
  Clock::time_point give_up = Clock::now() + grace_;
  while (!stop_) {
    bool interrupted = false;
    for (z3::context* ctx : contexts_) interrupted |= interrupt_query(*ctx);
    fired_ |= interrupted;
    if (interrupted && on_stuck_ && Clock::now() >= give_up) {
      std::function<void()> last_word = std::move(on_stuck_);
      on_stuck_ = nullptr;
      lock.unlock();  // the callback may end the process; nothing of ours is held meanwhile
      last_word();
      lock.lock();
    }
    wake_.wait_for(lock, std::chrono::milliseconds(50), [this] { return stop_; });
  }
}

}  // namespace arbc::verify
