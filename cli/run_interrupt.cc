#include "cli/run_interrupt.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>

namespace arbc::cli {

namespace {

// Written only by the signal handler (async-signal-safe: lock-free atomics, write(2)).
std::atomic<bool> interrupted{false};
std::atomic<int> signal_number{0};
int wake_fd = -1;  // the watchdog's pipe
struct sigaction previous_int, previous_term;

void on_signal(int sig) {
  interrupted.store(true);
  signal_number.store(sig);
  if (wake_fd >= 0) {
    char s = 's';
    [[maybe_unused]] ssize_t n = write(wake_fd, &s, 1);
  }
}

}  // namespace

RunInterrupt::RunInterrupt() {
  interrupted = false;
  signal_number = 0;
  if (pipe(pipe_) == 0) {
    fcntl(pipe_[1], F_SETFL, O_NONBLOCK);  // a handler must never block on a full pipe
    wake_fd = pipe_[1];
  }
  struct sigaction action = {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

RunInterrupt::~RunInterrupt() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  if (thread_.joinable()) {
    char q = 'q';
    [[maybe_unused]] ssize_t n = write(pipe_[1], &q, 1);
    thread_.join();
  }
  wake_fd = -1;
  for (int fd : pipe_)
    if (fd >= 0) close(fd);
}

const std::atomic<bool>* RunInterrupt::flag() const { return &interrupted; }

const char* RunInterrupt::signal_name() const {
  switch (signal_number.load()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "";
  }
}

void RunInterrupt::watch(double grace, std::function<double()> patience,
                         std::function<void(double)> give_up) {
  if (pipe_[0] < 0 || thread_.joinable()) return;
  patience_ = std::move(patience);
  give_up_ = std::move(give_up);
  thread_ = std::thread([this, grace] { watchdog(grace); });
}

bool RunInterrupt::run_returned() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (giving_up_) return false;
  returned_ = true;
  returned_cv_.notify_all();
  return true;
}

void RunInterrupt::watchdog(double grace) {
  char byte = 0;
  while (read(pipe_[0], &byte, 1) < 0) {  // EINTR: the handler ran on this thread
  }
  if (byte != 's') return;  // 'q': the run is over
  std::unique_lock<std::mutex> lock(mutex_);
  auto signalled = std::chrono::steady_clock::now();
  auto after = [&](double seconds) {
    return signalled + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(seconds));
  };
  if (returned_cv_.wait_until(lock, after(grace), [this] { return returned_; })) return;
  double waited = grace + std::max(0.0, patience_ ? patience_() : 0.0);
  if (returned_cv_.wait_until(lock, after(waited), [this] { return returned_; })) return;
  giving_up_ = true;
  lock.unlock();
  give_up_(waited);
  std::fflush(stdout);
  std::fflush(stderr);
  _exit(3);  // the executor thread is stuck: no destructor may wait for it
}

}  // namespace arbc::cli
