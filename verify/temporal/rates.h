// Environment rates in the unrolling (docs/design.md#properties-over-time): `given M.p every D;`
// says source M.p publishes at least every D from the start, so each connection into the port
// whose source is M.p handles a message (a step) by D and at most D after the previous one, up
// to the end of the observed run. The runtime hands every message of a source to every
// connection from it, so the constraint holds per connection in every real run: adding it
// removes no real behaviour.
#pragma once

#include <z3++.h>

#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

class Rates {
 public:
  // The rates of the sources of `shape`'s connections (none: every formula is true).
  Rates(const model::App& app, const PortShape& shape, z3::context& ctx);

  // Whether a message at the horizon itself belongs to the observed run. Included (a response's
  // window (t, t + D] ends there): a message due exactly at the horizon would be a step, so the
  // gap after the last step must be shorter than the period. After (a stability's last switch):
  // a message at that instant comes after the violation and changes nothing.
  enum class Horizon { Included, After };
  // Over the first `n` steps of `u`, observed until `horizon` (>= the last step's time): no
  // rated connection is silent for more than its period, from time 0 on.
  z3::expr up_to(const Unrolling& u, int n, const z3::expr& horizon, Horizon end) const;

  // Over the first `n` steps: a rule whose monitor accepts every message (accepts_every_message)
  // accepts on each of its steps, so a rated source's messages cannot all be rejected.
  z3::expr accepting(const Unrolling& u, int n) const;

  // How long a run the rated sources fill with more than `messages` messages into the port (0
  // with no rate): a search of `messages` steps sees only runs up to this long (shorter, for
  // a response's Included horizon), so a violation that needs a longer run is beyond it. Each
  // rated connection has a message by every multiple of its period.
  Nanos span(int messages) const;
  // How many messages the rated connections have by time t at the least (each one by every
  // multiple of its period up to t).
  int due_by(Nanos t) const;
  // Whether connection c of the port's shape has a rate.
  bool rated(int c) const;

  // The rates a verdict on this port relies on, in spec order (for the report).
  const std::vector<model::SourceRate>& used() const { return used_; }
  bool empty() const { return rated_.empty(); }

 private:
  // Connection c has a message at most `period` before `at` (less than `period`, `strictly`),
  // or `at` is within the first period, among the steps j < n.
  z3::expr recent(const Unrolling& u, int c, const z3::expr& period, int n, const z3::expr& at,
                  bool strictly) const;

  struct Rated {
    int connection;
    z3::expr period;
    Nanos nanos;
  };
  z3::context& ctx_;
  std::vector<Rated> rated_;
  std::vector<model::SourceRate> used_;
  std::vector<int> always_accept_;  // connections whose monitor accepts every message
};

// Whether rule `c`'s monitor accepts every message: no `accept`, no `script`, and no expression
// that can fail at run time (an index, a call, arithmetic), so the runtime never drops its
// message as rejected or for a monitor error. Such a rule's steps accept in the unrolling.
bool accepts_every_message(const model::Connection& c);

// "given LookAround.gaze every 200ms (spec:3)", for the reports.
std::string rate_words(const model::SourceRate& r);

}  // namespace arbc::verify::temporal
