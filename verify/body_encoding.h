// A rule's body as a Z3 formula over one input message (docs/design.md#the-proof): whether
// the generated monitor accepts the message, and the value it delivers.
//
// Exact for lists of any length where the body reads its lists only through `len` and indexes
// that are constants below the capacity (the elements encoded), and else for lists of at most
// the capacity (the list bound): `bounded` says which, and the data query assumes the bound only
// for bodies that need it (docs/checks.md#message-data). In the
// machine's arithmetic (verify/lua_number.h: IEEE doubles, 64-bit ints that wrap). What cannot
// be encoded exactly (string order and length, `%` on floats of the message, a list-valued
// `var`) makes the rule *opaque* for data: `opaque` says why, and no
// data question is asked about the rule. Monitor state is abstracted soundly: a `var` holds an
// unknown value of its type on each message (any value earlier messages could have left),
// `now()` is an unknown time; `set`, `unset`, `throttle` and `every` do not change what is
// accepted or emitted (their effect on events is the effective guard's business).
#pragma once

#include <z3++.h>

#include <optional>
#include <string>
#include <vector>

#include "core/body.h"
#include "verify/sym_value.h"

namespace arbc::verify {

// An `accept` (or the condition of an `if`) with its tracking literal, for explanations.
struct AcceptTracker {
  z3::expr literal;
  int line = 0;
};

// A norm (or dist) left abstract (encode_body's abstract_lengths): `result` is the
// uninterpreted arbc_norm of the three components, with only lua::norm_facts about it; `exact`
// is what the monitor computes, lua::norm's circuit, which is large (a multiplication, an
// addition and a square root of doubles, each rounded, bit by bit). A caller adds
// `result == exact` only where a model needs it (DataQuery::check): a question the facts
// already answer is then answered without the circuit.
struct AbstractLength {
  z3::expr result;
  z3::expr exact;
  std::vector<z3::expr> components;  // the three floats whose norm it is
};

struct EncodedBody {
  std::string opaque;               // non-empty: why the body is opaque for data; the rest is unset
  z3::expr accepts;                 // the monitor accepts: no `accept` fails and every value exists
  std::optional<SymValue> emitted;  // what update() delivers when it accepts
  std::vector<z3::expr> side;       // definitions of auxiliary constants (square roots)
  // Each `accept E` is encoded as `literal implies E`: assume every literal to ask about the
  // body; an unsat core of them names the accepts that matter.
  std::vector<AcceptTracker> trackers;
  std::vector<std::string> abstracted;                  // state read: "var x", "now()"
  std::vector<std::pair<std::string, SymValue>> state;  // the abstracted values, by name
  std::vector<AbstractLength> lengths;                  // with abstract_lengths only
  // The encoding is exact only for lists of at most their capacity: it reads elements at an
  // index it does not know (`xs[i]`, `+` and `==` of lists; min_by, max_by, min, max of an
  // open list without stand-ins past its capacity). Without it, a list of any length is
  // encoded exactly: its elements past the capacity are read only through the stand-ins.
  bool bounded = false;
  // How many reads scanned a list's stand-ins past its capacity (SymValue::tail): exact only
  // while all encodings over one message together make no more such reads than a list has
  // slots (DataQuery counts them).
  int tail_reads = 0;

  explicit EncodedBody(z3::context& ctx) : accepts(ctx.bool_val(false)) {}
};

// Encodes `body` on the message `msg`; fresh constants are named after `prefix` (unique per
// rule and message). With `abstract_lengths`, the norm of floats is left abstract (`lengths`):
// the encoding then over-approximates the body (an unsat answer holds for the machine, a
// model holds only once every length in it agrees with its `exact`). `clock` names the run's
// clock (as ROS 2 time) that age() reads: encodings given one name read one clock, as the rules
// that judge one message do at its one instant; "" gives each call a clock of its own.
EncodedBody encode_body(z3::context& ctx, const model::Body& body, const SymValue& msg,
                        const std::string& prefix, bool abstract_lengths = false,
                        const std::string& clock = "");

}  // namespace arbc::verify
