// Which event containers an event lives in, and when two containers hold one fact
// (docs/design.md#events-and-lifetimes). Every arbitrated port owns a container, so the same
// event name in two ports is two facts: the resource check (verify/resource_checks.h), the
// properties over time and `arbc test` read an event where it lives, never "anywhere".
#pragma once

#include <string_view>
#include <vector>

#include "core/app_model.h"

namespace arbc::model {

// The connections into `port` that can put `event` into its container: those whose monitor
// sets it (a `script` rule: any event of the port), the rule whose activity event it is, and the
// feeds that carry it.
std::vector<const Connection*> setters_into(const App& app, std::string_view port,
                                            std::string_view event);

// Whether `c` is the feed of a delivery event: its stream is what an arbitrated port delivers
// (docs/language.md#delivery-events), so the runtime runs it in the task of each delivery.
bool is_delivery_feed(const App& app, const Connection& c);

// Whether `event` is one fact in the containers of ports `a` and `b`: it can be set into both,
// and only by delivery feeds, from the same ports. Those feeds run in the task of the delivery
// that sets them, one after the other, so no decision falls between them. Anything else that
// puts an event into two containers does it in separate steps (each feed takes a message in its
// own task, a monitor sets only its own port's container), and a decision may fall in between.
bool one_fact(const App& app, std::string_view event, std::string_view a, std::string_view b);

// The arbitrated ports whose containers something can put `event` into.
std::vector<std::string> ports_holding(const App& app, std::string_view event);

}  // namespace arbc::model
