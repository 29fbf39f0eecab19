#include "lsp/client_watch.h"

#include <signal.h>

#include <cerrno>

namespace arbc::lsp {

bool process_exists(int pid) { return pid > 0 && (kill(pid, 0) == 0 || errno != ESRCH); }

ClientWatch::ClientWatch(int pid, std::chrono::milliseconds period, std::function<void()> gone)
    : pid_(pid), period_(period), gone_(std::move(gone)), thread_([this] { loop(); }) {}

ClientWatch::~ClientWatch() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void ClientWatch::loop() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, period_, [this] { return stopping_; })) {
    if (process_exists(pid_)) continue;
    lock.unlock();
    gone_();
    return;
  }
}

}  // namespace arbc::lsp
