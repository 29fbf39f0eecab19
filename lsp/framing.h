// The LSP base protocol: JSON-RPC messages framed by a `Content-Length` header on a byte
// stream (stdin/stdout for `arbc lsp`). Our own small implementation over nlohmann-json; why
// no library is in docs/editors.md#the-server.
#pragma once

#include <atomic>
#include <istream>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>

namespace arbc::lsp {

// Larger messages are refused (their bytes skipped) rather than buffered.
inline constexpr size_t kMaxMessageBytes = 256u << 20;

// Reads one message body. nullopt at the end of the stream (`err` empty) or when the stream
// ends inside a message (`err` says so). A header block without a usable Content-Length, or
// one over kMaxMessageBytes, sets `err` but returns an empty body so that the caller can log
// it and go on with the next message.
std::optional<std::string> read_message(std::istream& in, std::string* err);

// Writes framed messages; one writer thread at a time (replies and notifications come from
// the request thread and the analysis workers).
class MessageWriter {
 public:
  explicit MessageWriter(std::ostream& out) : out_(out) {}
  void write(const std::string& body);
  // Whether a write failed (the client closed its end): nobody reads what we send any more.
  bool broken() const { return broken_; }

 private:
  std::ostream& out_;
  std::mutex mutex_;
  std::atomic<bool> broken_{false};
};

}  // namespace arbc::lsp
