// The spec names of a twist_mux configuration's inputs and locks, and the order the spec lists
// them in (twist_mux_spec.cc writes with them).
#pragma once

#include <string>
#include <vector>

#include "import/twist_mux/twist_mux_config.h"

namespace arbc::twist_mux {

struct Named {
  const MuxEntry* entry = nullptr;
  std::string rule;    // an input's rule; a lock's stem
  std::string module;  // the module that publishes it
  // An input: `<rule>_active`, which its body sets for its timeout on each message (twist_mux's
  // stamp); a lock: the name of its `lock` declaration, `<stem>_lock`.
  std::string event;
  // A lock with a timeout: its heard event, `<stem>_lock_heard` (the lock fails closed); an input
  // without one that some input is below: `<rule>_heard`, present from its first message on and
  // unknown (closed) before, as twist_mux counts such an input active from the start.
  std::string heard;
};

struct MuxNames {
  std::vector<Named> inputs;  // priority above 0, highest first, the files' order among equals
  std::vector<Named> locks;   // those that block some input, in the files' order
  std::string base;           // the module twist_mux publishes to
};

MuxNames name_mux(const MuxConfig& config);

// The terms of an input's `when` after its own activity: not active (nor heard, for one
// without a timeout) for each input above it, and `not LOCK` for each lock above it.
std::vector<std::string> blocking_terms(const MuxNames& names, const Named& input);

// Whether the lock blocks the input (a priority below the lock's).
inline bool blocks(const Named& lock, const Named& input) {
  return input.entry->priority < lock.entry->priority;
}

}  // namespace arbc::twist_mux
