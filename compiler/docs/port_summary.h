// What the diagrams of `arbc docs` say about one arbitrated port: its rules in order (highest
// first under `by priority`), each with the `when` the user wrote and its hold, and the event
// feeds into the port with the events each carries. The core model keeps only the lowered
// constraint, so the `when` is recovered by dropping the `not act_j` terms that lowering adds
// for the higher rules under `by priority` (docs/design.md#priorities-and-holds).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::docs {

struct RuleSummary {
  const model::Connection* connection = nullptr;
  std::string when;           // constraint text without the priority terms; "true" if none
  std::optional<Nanos> hold;  // for a `by priority` rule that has one
  // Events its monitor sets on every accepting path (activity events aside): they count in
  // its effective guard, so they explain why it does not overlap a rule that reads them.
  std::vector<std::string> sets;
};

struct FeedSummary {
  const model::Connection* connection = nullptr;
  std::vector<std::string> events;  // what it sets or unsets in the port's container, sorted
  bool delivered = false;           // delivery events: it reads what its source port delivers
};

struct PortSummary {
  const model::ArbitratedPort* port = nullptr;
  std::vector<RuleSummary> rules;  // in the port's rule order
  std::vector<FeedSummary> feeds;  // in model order
};

// `into` is every connection into the port (App::connections_into, or an index of them).
PortSummary summarize_port(const model::App& app, const model::ArbitratedPort& port,
                           std::span<const model::Connection* const> into);

}  // namespace arbc::docs
