// Selection constraints: boolean formulas over event names (docs/design.md#the-message-path).
//
// Text form, as passed to PortMonitor.setConstraint and stored in app.json:
//   constraint := or ;  or := and ('or' and)* ;  and := unary ('and' unary)* ;
//   unary := 'not' unary | '(' or ')' | 'true' | 'false' | EVENT
// EVENT is an identifier [A-Za-z_][A-Za-z0-9_]* other than the keywords. Names are whole
// tokens, so `e` and `e_ball` never interfere (YARP's substring substitution does).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace arbc {

struct Constraint {
  enum class Op { True, False, Event, Not, And, Or };
  Op op = Op::True;
  std::string event;             // Op::Event
  std::vector<Constraint> args;  // Op::Not: one; Op::And / Op::Or: two or more

  static Constraint constant(bool value);
  static Constraint event_ref(std::string name);
  static Constraint negate(Constraint c);
  // Flatten nested and/or and fold constants; an empty conjunction is true, an empty
  // disjunction false.
  static Constraint conjunction(std::vector<Constraint> args);
  static Constraint disjunction(std::vector<Constraint> args);

  // Canonical text with the fewest parentheses: "not e_taken and (a or b)".
  std::string to_string() const;
  void collect_events(std::set<std::string>& out) const;
  bool operator==(const Constraint&) const = default;
};

// The constraint in `text`; nullopt and *err on failure ("expected ')' at offset 11").
std::optional<Constraint> parse_constraint(std::string_view text, std::string* err);

// The same with the error's byte offset as a number, for tools that point into the text (the
// YARP importer's messages, the fuzzer); tests use it for brevity.
struct ConstraintParse {
  bool ok = false;
  Constraint constraint;
  std::string error;  // what is wrong, for the user
  size_t offset = 0;  // byte offset of the error in the text
};

// Nesting deeper than this is rejected, so hostile text cannot exhaust the stack.
inline constexpr int kMaxConstraintDepth = 200;

ConstraintParse parse_constraint(std::string_view text);

// Evaluates the tree directly against a set of present events. Slow; a reference for tests
// and tools. The message path uses CompiledConstraint.
bool evaluate(const Constraint& c, const std::set<std::string>& present);

// The same with presence asked of `present(name)` (a container, the live status): the one
// definition of a constraint's meaning over events, inlined for each way of asking.
template <class Present>
bool evaluate_with(const Constraint& c, const Present& present) {
  switch (c.op) {
    case Constraint::Op::True:
      return true;
    case Constraint::Op::False:
      return false;
    case Constraint::Op::Event:
      return present(c.event);
    case Constraint::Op::Not:
      return !evaluate_with(c.args[0], present);
    case Constraint::Op::And:
      for (const Constraint& a : c.args)
        if (!evaluate_with(a, present)) return false;
      return true;
    case Constraint::Op::Or:
      for (const Constraint& a : c.args)
        if (evaluate_with(a, present)) return true;
      return false;
  }
  return false;
}

}  // namespace arbc
