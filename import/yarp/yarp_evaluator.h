// YARP 3.12's evaluation of a port monitor constraint, step for step (MonitorLua::canAccept in
// src/carriers/portmonitor_carrier/lua/MonitorLua.cpp; docs/yarp.md#what-yarp-does):
//   1. split the text at spaces, after turning `(` and `)` into spaces;
//   2. for each piece that is not and/or/not/true/false, replace EVERY occurrence of it as a
//      substring of the whole text by `true` or `false` (is an event of that name present?);
//   3. run `return <text>` as Lua; a Lua error or a value that is not a boolean means false.
// Step 2 is why an event name that is a substring of another name, or of a keyword, corrupts
// the result. arbc runs this to find the states where YARP's answer differs from the
// constraint's meaning, and proves exclusivity with YARP's answers.
#pragma once

#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/constraint.h"
#include "runtime/lua_sandbox.h"

namespace arbc::yarp {

// The pieces YARP looks up, in the order it looks them up (duplicates kept).
std::vector<std::string> yarp_lookups(std::string_view constraint);

// The text after step 2 for the given present events.
std::string yarp_substitute(std::string_view constraint, const std::set<std::string>& present);

struct YarpVerdict {
  enum class Result { True, False, NotBoolean, LuaError };
  Result result = Result::False;
  std::string text;   // what YARP hands to Lua, without the leading "return "
  std::string error;  // the Lua error, for LuaError
  bool accepts() const { return result == Result::True; }
};

class YarpEvaluator {
 public:
  // nullptr only if a Lua state cannot be created.
  static std::unique_ptr<YarpEvaluator> create();
  // Steps 1-3 for `constraint` (as set with setConstraint) when `present` events are set.
  YarpVerdict evaluate(std::string_view constraint, const std::set<std::string>& present);

 private:
  explicit YarpEvaluator(std::unique_ptr<LuaSandbox> box) : box_(std::move(box)) {}
  std::unique_ptr<LuaSandbox> box_;
};

// A constraint as written, and as YARP evaluates it.
struct ConstraintMeaning {
  std::string text;                  // trimmed like YARP (spaces at both ends)
  bool parsed = false;               // arbc's constraint grammar accepts it
  Constraint written;                // when parsed
  std::string parse_error;           // when not
  std::vector<std::string> events;   // the distinct pieces YARP looks up, sorted
  bool simulated = false;            // every state was tried (at most kMaxSimulatedEvents)
  Constraint yarp;                   // what YARP selects on, over `events`
  bool differs = false;              // some state where YARP's answer is not the written one
  std::vector<std::string> witness;  // such a state (fewest events present), when differs
  YarpVerdict witness_verdict;       // YARP's answer there
  bool written_at_witness = false;   // the written constraint's answer there (when parsed)
};

inline constexpr size_t kMaxSimulatedEvents = 12;

// The first replacement YARP makes inside a longer word when `present` events are set: the
// name replaced and the word it sat in (another name, a keyword, or a `true`/`false` YARP
// wrote for an earlier name).
struct Corruption {
  std::string name, word;
  bool found = false;
};
Corruption first_corruption(std::string_view constraint, const std::set<std::string>& present);

// Parses `text` with arbc's grammar and runs YARP's evaluation on every event state.
ConstraintMeaning constraint_meaning(YarpEvaluator& evaluator, std::string_view text);

}  // namespace arbc::yarp
