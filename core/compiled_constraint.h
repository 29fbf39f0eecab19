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

// A set of event ids.
class EventMask {
 public:
  void set(int id) {
    grow(id);
    words_[id >> 6] |= uint64_t{1} << (id & 63);
  }
  void reset(int id) {
    if ((id >> 6) < static_cast<int>(words_.size())) words_[id >> 6] &= ~(uint64_t{1} << (id & 63));
  }
  bool test(int id) const {
    return (id >> 6) < static_cast<int>(words_.size()) && (words_[id >> 6] >> (id & 63)) & 1;
  }
  void clear() { words_.assign(words_.size(), 0); }
  uint64_t word(int i) const { return i < static_cast<int>(words_.size()) ? words_[i] : 0; }
  int word_count() const { return static_cast<int>(words_.size()); }

 private:
  void grow(int id) {
    size_t need = static_cast<size_t>(id >> 6) + 1;
    if (words_.size() < need) words_.resize(need, 0);
  }
  std::vector<uint64_t> words_;
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
    if (is_cube_) {
      // Up to 64 events (every port of the reference apps): one word, no loop.
      if (required_.size() <= 1) {
        uint64_t w = present.word(0);
        return (w & required0_) == required0_ && (w & forbidden0_) == 0;
      }
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
  uint64_t required0_ = 0, forbidden0_ = 0;  // word 0 of the masks, for the one-word case
  std::vector<Instr> program_;
};

}  // namespace arbc
