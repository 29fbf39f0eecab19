// Constraints compiled once, when set, into a form evaluated without parsing or allocation
// (docs/design.md#the-message-path). Events are numbered per container by an EventIndex; the set of
// present events is a bit mask.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/constraint.h"

namespace arbc {

// Dense numbering of the events of one event container.
class EventIndex {
 public:
  int intern(std::string_view name);      // the event's id, adding it when new
  int find(std::string_view name) const;  // -1 when unknown
  const std::string& name(int id) const { return names_[id]; }
  int size() const { return static_cast<int>(names_.size()); }

 private:
  std::vector<std::string> names_;
  std::unordered_map<std::string, int> ids_;
};

// A set of event ids. The first 64 ids (every port of the reference apps) live in a word
// held inline, so a decision reads one word with no bounds check and no indirection; higher
// ids spill into a vector.
class EventMask {
 public:
  void set(int id) {
    if (id < 64) {
      first_ |= uint64_t{1} << id;
      return;
    }
    size_t w = static_cast<size_t>(id >> 6) - 1;
    if (rest_.size() <= w) rest_.resize(w + 1, 0);
    rest_[w] |= uint64_t{1} << (id & 63);
  }
  void reset(int id) {
    if (id < 64) {
      first_ &= ~(uint64_t{1} << id);
    } else if (static_cast<size_t>(id >> 6) - 1 < rest_.size()) {
      rest_[static_cast<size_t>(id >> 6) - 1] &= ~(uint64_t{1} << (id & 63));
    }
  }
  bool test(int id) const { return (word(id >> 6) >> (id & 63)) & 1; }
  void clear() {
    first_ = 0;
    rest_.assign(rest_.size(), 0);
  }
  uint64_t first_word() const { return first_; }
  uint64_t word(int i) const {
    if (i == 0) return first_;
    return static_cast<size_t>(i) - 1 < rest_.size() ? rest_[static_cast<size_t>(i) - 1] : 0;
  }

 private:
  uint64_t first_ = 0;
  std::vector<uint64_t> rest_;  // words 1.. (ids 64 and up)
};

// A conjunction of literals: the events whose bits are in `required` present and those in
// `forbidden` absent (bit sets by EventIndex id, of equal length).
struct Cube {
  std::vector<uint64_t> required, forbidden;
  // Some event both required and forbidden: no state satisfies the cube.
  bool contradictory() const;
};

// `c` as a cube when it is `true` or a conjunction of events and negated events, its events
// interned in `index`; nullopt for any other shape. The one cube decomposition: the runtime's
// compiled constraints and the verifier's shortcut both use it.
std::optional<Cube> as_cube(const Constraint& c, EventIndex& index);

class CompiledConstraint {
 public:
  CompiledConstraint() = default;  // the constant true
  static CompiledConstraint compile(const Constraint& c, EventIndex& index);

  bool evaluate(const EventMask& present) const {
    // Up to 64 events (every port of the reference apps): one masked compare of one word.
    if (one_word_) return (present.first_word() & care0_) == required0_;
    if (is_cube_) {
      for (size_t i = 0; i < required_.size(); ++i) {
        uint64_t w = present.word(static_cast<int>(i));
        if ((w & required_[i]) != required_[i] || (w & forbidden_[i]) != 0) return false;
      }
      return true;
    }
    return run_program(present);
  }

 private:
  // A postfix program for formulas that are not a conjunction of literals.
  enum class OpCode : uint8_t { PushTrue, PushFalse, PushEvent, Not, And, Or };
  struct Instr {
    OpCode op;
    uint32_t arg;  // event id for PushEvent; operand count for And / Or
  };
  bool run_program(const EventMask& present) const;

  bool is_cube_ = true;  // a conjunction of literals: two mask comparisons per word
  std::vector<uint64_t> required_, forbidden_;
  // A cube over ids below 64: present iff (word 0 & care0_) == required0_, where care0_ is
  // required | forbidden (a non-contradictory cube has them disjoint).
  bool one_word_ = true;
  uint64_t required0_ = 0, care0_ = 0;
  std::vector<Instr> program_;
};

}  // namespace arbc
