// A thread that runs a task per key (a document) once the key has been quiet for a delay:
// typing schedules the same document again and again, and only the last schedule runs.
// Keeps slow work (checking, proving) off the thread that reads the client's messages.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace arbc::lsp {

class DebouncedWorker {
 public:
  using Task = std::function<void(const std::string& key)>;
  DebouncedWorker(std::chrono::milliseconds delay, Task task);
  ~DebouncedWorker();  // stops: a running task finishes, pending ones are dropped
  DebouncedWorker(const DebouncedWorker&) = delete;
  DebouncedWorker& operator=(const DebouncedWorker&) = delete;

  void schedule(const std::string& key);  // runs `key` after the delay (restarts it)
  void cancel(const std::string& key);
  void stop();

 private:
  void loop();
  std::chrono::milliseconds delay_;
  Task task_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, std::chrono::steady_clock::time_point> due_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace arbc::lsp
