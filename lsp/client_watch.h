// Watches the client's process (the `processId` of `initialize`): the LSP asks a server to
// exit when its client is gone, even if the pipes stay open (a wrapper that outlives the
// editor holds them). docs/reliability.md#the-language-server-arbc-lsp.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace arbc::lsp {

class ClientWatch {
 public:
  // Checks every `period` that process `pid` exists; once it does not, calls `gone` (once,
  // on the watch's thread) and stops.
  ClientWatch(int pid, std::chrono::milliseconds period, std::function<void()> gone);
  ~ClientWatch();  // stops the thread
  ClientWatch(const ClientWatch&) = delete;
  ClientWatch& operator=(const ClientWatch&) = delete;

 private:
  void loop();
  int pid_;
  std::chrono::milliseconds period_;
  std::function<void()> gone_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

// Whether process `pid` exists (a process of another user counts; a zombie too).
bool process_exists(int pid);

}  // namespace arbc::lsp
