#include "core/compiled_constraint.h"

#include <algorithm>
#include <memory>

namespace arbc {

int EventIndex::intern(std::string_view name) {
  auto it = ids_.find(std::string(name));
  if (it != ids_.end()) return it->second;
  int id = static_cast<int>(names_.size());
  names_.emplace_back(name);
  ids_.emplace(names_.back(), id);
  return id;
}

int EventIndex::find(std::string_view name) const {
  auto it = ids_.find(std::string(name));
  return it == ids_.end() ? -1 : it->second;
}

namespace {

// A literal is an event or its negation.
bool as_literal(const Constraint& c, const Constraint** event, bool* positive) {
  if (c.op == Constraint::Op::Event) {
    *event = &c;
    *positive = true;
    return true;
  }
  if (c.op == Constraint::Op::Not && c.args[0].op == Constraint::Op::Event) {
    *event = &c.args[0];
    *positive = false;
    return true;
  }
  return false;
}

void set_bit(std::vector<uint64_t>& words, int id) {
  size_t w = static_cast<size_t>(id >> 6);
  if (words.size() <= w) words.resize(w + 1, 0);
  words[w] |= uint64_t{1} << (id & 63);
}

}  // namespace

bool Cube::contradictory() const {
  for (size_t i = 0; i < required.size(); ++i)
    if (required[i] & forbidden[i]) return true;
  return false;
}

std::optional<Cube> as_cube(const Constraint& c, EventIndex& index) {
  std::vector<const Constraint*> conjuncts;
  if (c.op == Constraint::Op::And) {
    for (const Constraint& a : c.args) conjuncts.push_back(&a);
  } else if (c.op != Constraint::Op::True) {
    conjuncts.push_back(&c);
  }
  Cube cube;
  for (const Constraint* k : conjuncts) {
    const Constraint* ev;
    bool positive;
    if (!as_literal(*k, &ev, &positive)) return std::nullopt;
    int id = index.intern(ev->event);
    set_bit(positive ? cube.required : cube.forbidden, id);
  }
  size_t n = std::max(cube.required.size(), cube.forbidden.size());
  cube.required.resize(n, 0);
  cube.forbidden.resize(n, 0);
  return cube;
}

CompiledConstraint CompiledConstraint::compile(const Constraint& c, EventIndex& index) {
  CompiledConstraint out;
  // Fast path: true, or a conjunction of literals (the common shape of rule guards). A literal
  // and its negation together is unsatisfiable: kept as a program for clarity.
  std::optional<Cube> cube = as_cube(c, index);
  if (cube && !cube->contradictory()) {
    out.required_ = std::move(cube->required);
    out.forbidden_ = std::move(cube->forbidden);
    out.one_word_ = out.required_.size() <= 1;
    if (!out.required_.empty()) {
      out.required0_ = out.required_[0];
      out.care0_ = out.required_[0] | out.forbidden_[0];
    }
    return out;
  }
  out.is_cube_ = false;
  out.one_word_ = false;
  // Post-order emission.
  struct Emitter {
    EventIndex& index;
    std::vector<Instr>& program;
    void emit(const Constraint& k) {
      switch (k.op) {
        case Constraint::Op::True:
          program.push_back({OpCode::PushTrue, 0});
          break;
        case Constraint::Op::False:
          program.push_back({OpCode::PushFalse, 0});
          break;
        case Constraint::Op::Event:
          program.push_back({OpCode::PushEvent, static_cast<uint32_t>(index.intern(k.event))});
          break;
        case Constraint::Op::Not:
          emit(k.args[0]);
          program.push_back({OpCode::Not, 0});
          break;
        case Constraint::Op::And:
        case Constraint::Op::Or:
          for (const Constraint& a : k.args) emit(a);
          program.push_back({k.op == Constraint::Op::And ? OpCode::And : OpCode::Or,
                             static_cast<uint32_t>(k.args.size())});
          break;
      }
    }
  };
  Emitter{index, out.program_}.emit(c);
  return out;
}

bool CompiledConstraint::run_program(const EventMask& present) const {
  // A small fixed stack covers ordinary constraints; deep ones fall back to the heap.
  constexpr size_t kInline = 64;
  bool inline_stack[kInline] = {};
  std::vector<bool> heap_stack;
  bool* stack = inline_stack;
  if (program_.size() > kInline) {
    heap_stack.resize(program_.size());
    // std::vector<bool> has no data(); use a plain buffer instead.
  }
  std::vector<char> big;
  if (program_.size() > kInline) {
    big.resize(program_.size());
    stack = reinterpret_cast<bool*>(big.data());
  }
  size_t top = 0;
  for (const Instr& in : program_) {
    switch (in.op) {
      case OpCode::PushTrue:
        stack[top++] = true;
        break;
      case OpCode::PushFalse:
        stack[top++] = false;
        break;
      case OpCode::PushEvent:
        stack[top++] = present.test(static_cast<int>(in.arg));
        break;
      case OpCode::Not:
        stack[top - 1] = !stack[top - 1];
        break;
      case OpCode::And:
      case OpCode::Or: {
        bool is_and = in.op == OpCode::And;
        bool acc = is_and;
        for (uint32_t i = 0; i < in.arg; ++i) {
          bool v = stack[--top];
          acc = is_and ? (acc && v) : (acc || v);
        }
        stack[top++] = acc;
        break;
      }
    }
  }
  return stack[0];
}

}  // namespace arbc
