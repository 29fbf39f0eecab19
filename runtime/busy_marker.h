// What the executor thread is running now, readable from any other thread: a watchdog that must
// name a callback stuck past its budget when Ctrl-C cannot stop it (docs/reliability.md,
// "A stuck monitor"). One writer (the executor thread), any number of readers; no lock, so
// marking costs a few stores per callback.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

namespace arbc {

class BusyMarker {
 public:
  // kind: "monitor", "module", "environment" or "transport" (closing); `name` must outlive the
  // callback.
  // A seqlock without fences (ThreadSanitizer does not model them): the serial goes odd before the
  // fields change and even after; the fields are stored with release, so a reader that sees a
  // new field also sees the odd serial when it checks again.
  void enter(const char* kind, const std::string* name, const char* callback) {
    uint64_t serial = begin_write();
    kind_.store(kind, std::memory_order_release);
    name_.store(name, std::memory_order_release);
    callback_.store(callback, std::memory_order_release);
    end_write(serial);
  }
  void leave() {
    uint64_t serial = begin_write();
    kind_.store(nullptr, std::memory_order_release);
    end_write(serial);
  }

  struct Snapshot {
    uint64_t serial = 0;               // changes with every callback entered or left
    std::string kind, name, callback;  // kind empty: between callbacks
  };
  // A consistent view (retried while the writer moves on).
  Snapshot snapshot() const {
    Snapshot s;
    for (int attempt = 0; attempt < 100; ++attempt) {
      s.serial = serial_.load(std::memory_order_acquire);
      if (s.serial % 2 == 1) continue;  // the writer is between begin_write and end_write
      const char* kind = kind_.load(std::memory_order_acquire);
      const std::string* name = name_.load(std::memory_order_acquire);
      const char* callback = callback_.load(std::memory_order_acquire);
      if (serial_.load(std::memory_order_relaxed) != s.serial) continue;
      s.kind = kind ? kind : "";
      s.name = kind && name ? *name : "";
      s.callback = kind && callback ? callback : "";
      return s;
    }
    return s;
  }

 private:
  // Only the writer changes the serial, so it reads it once per write and carries it in a
  // register: loading it again right after storing it chained each marking through the
  // store-to-load forwarding latency, about 20 cycles per callback.
  uint64_t begin_write() {
    uint64_t odd = serial_.load(std::memory_order_relaxed) + 1;
    serial_.store(odd, std::memory_order_relaxed);
    return odd;
  }
  void end_write(uint64_t odd) { serial_.store(odd + 1, std::memory_order_release); }

  std::atomic<uint64_t> serial_{0};
  std::atomic<const char*> kind_{nullptr};
  std::atomic<const std::string*> name_{nullptr};
  std::atomic<const char*> callback_{nullptr};
};

// Marks a callback for as long as it is alive.
class BusyScope {
 public:
  BusyScope(BusyMarker& marker, const char* kind, const std::string& name, const char* callback)
      : marker_(marker) {
    marker_.enter(kind, &name, callback);
  }
  ~BusyScope() { marker_.leave(); }
  BusyScope(const BusyScope&) = delete;
  BusyScope& operator=(const BusyScope&) = delete;

 private:
  BusyMarker& marker_;
};

}  // namespace arbc
