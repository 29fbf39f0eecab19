#include "lsp/debounced_worker.h"

namespace arbc::lsp {

DebouncedWorker::DebouncedWorker(std::chrono::milliseconds delay, Task task)
    : delay_(delay), task_(std::move(task)), thread_([this] { loop(); }) {}

DebouncedWorker::~DebouncedWorker() { stop(); }

void DebouncedWorker::schedule(const std::string& key) {
  {
    std::lock_guard lock(mutex_);
    due_[key] = std::chrono::steady_clock::now() + delay_;
  }
  wake_.notify_one();
}

void DebouncedWorker::cancel(const std::string& key) {
  std::lock_guard lock(mutex_);
  due_.erase(key);
}

void DebouncedWorker::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void DebouncedWorker::loop() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    if (due_.empty()) {
      wake_.wait(lock);
      continue;
    }
    auto next = due_.begin();
    for (auto it = due_.begin(); it != due_.end(); ++it)
      if (it->second < next->second) next = it;
    if (std::chrono::steady_clock::now() < next->second) {
      // A copy: wait_until reads its deadline again after waking, and cancel() may have freed
      // the map node meanwhile (a document closed while its analysis waited).
      const auto when = next->second;
      wake_.wait_until(lock, when);
      continue;
    }
    std::string key = next->first;
    due_.erase(next);
    lock.unlock();
    task_(key);
    lock.lock();
  }
}

}  // namespace arbc::lsp
