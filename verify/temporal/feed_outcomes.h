// What one message does to a feed's events in the temporal model (issue 38 item 7). The
// runtime's generated feed evaluates every event it carries on each message of its source, in
// one Lua call (compiler/codegen): a derived event `event e = M.p : PRED` is set when PRED holds
// on the message and removed when it does not (kept, with `for D`: it lapses D after the last
// message it held on); a status flag of `events from M.p { ... }` is set when the list holds the
// flag and removed when it does not, lifetime or not. So the derived events of one source are
// decided together by one value, and a combination no value gives (`s.v > 0` and `s.v < 0`) is
// never what a message does, nor what any state shows of the events without a lifetime.
#pragma once

#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

// Marks the entries of each feed into the port that its messages decide (Entry::by_message)
// and adds the combinations no message gives (PortShape::excluded_outcomes with `feed`, and
// excluded_at_start). A feed whose Lua may fail on some message (a predicate reading a value
// that does not exist, or one the data encoding cannot answer for every message: opaque, or
// exact only for short lists, which a feed does not drop) stays free: a failure leaves the
// events after the failing one as they were. `data` null: only status flags are decided.
void add_feed_outcomes(const model::App& app, PortShape& shape, DataQuery* data);

// The flag of the status list that sets `event` (a status event: fed, no predicate): its
// recorded flag, else its name (`events from M.p { e }`, or an app.json from before flags).
std::string status_flag(const model::Event& event);

}  // namespace arbc::verify::temporal
