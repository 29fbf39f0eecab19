#include "verify/temporal/feed_outcomes.h"

#include <string>
#include <vector>

#include "verify/temporal/own_delivery.h"

namespace arbc::verify::temporal {
namespace {

// At most this many derived events of one feed are asked about together (2^n questions);
// with more, each pair is (a pair no value gives is excluded all the same).
constexpr size_t kMostJointFeedEvents = 4;

// Whether every message of `source` has a value for `p` that the encoding answers for exactly.
bool decided(DataQuery& data, const std::string& source, const model::BodyExpr& p) {
  const model::Connection& m = data.pass_through(source);
  if (!data.predicate_opaque_reason(m, p).empty()) return false;
  if (data.bounded(m, &p, false) || data.bounded(m, &p, true)) return false;
  return !data.predicate_range(m, p).can_fail;
}

// The entries of feed `f` (its index among the shape's connections) if its messages decide all
// of them; empty otherwise.
std::vector<size_t> decided_entries(const model::App& app, const PortShape& shape, int f,
                                    DataQuery* data) {
  const model::Connection& feed = *shape.connections[static_cast<size_t>(f)];
  std::vector<size_t> out;
  for (size_t q = 0; q < shape.entries.size(); ++q) {
    const Entry& e = shape.entries[q];
    if (e.owner != f) continue;
    const model::Event* event = app.find_event(e.event);
    if (e.activity || e.own_delivery() || !event || event->source != feed.source) return {};
    // A status flag (no predicate) is decided by the list; a derived event, by its predicate.
    if (event->predicate && !(data && decided(*data, feed.source, *event->predicate))) return {};
    out.push_back(q);
  }
  return out;
}

// The combinations of `qs` (derived entries of one feed) that no message gives: each set of
// them exactly where its predicate holds. With `start`, the all-absent one is kept (no message
// yet).
void exclude(PortShape& shape, int f, const std::vector<size_t>& qs, DataQuery& data,
             std::vector<PortShape::ExcludedOutcome>& out, bool start) {
  const model::Connection& m = data.pass_through(shape.connections[static_cast<size_t>(f)]->source);
  for (unsigned mask = start ? 1 : 0; mask < (1u << qs.size()); ++mask) {
    std::vector<DataSide> sides;
    for (size_t i = 0; i < qs.size(); ++i)
      sides.push_back({&m, shape.entries[qs[i]].predicate, !(mask >> i & 1u)});
    if (data.ask(sides, nullptr, nullptr) != Answer::Unsat) continue;
    PortShape::ExcludedOutcome x{f, {}, true};
    for (size_t i = 0; i < qs.size(); ++i) x.sets.emplace_back(qs[i], (mask >> i & 1u) != 0);
    out.push_back(std::move(x));
  }
}

// exclude() over all of `qs` together when few, else over each pair.
void exclude_joint(PortShape& shape, int f, const std::vector<size_t>& qs, DataQuery& data,
                   std::vector<PortShape::ExcludedOutcome>& out, bool start) {
  if (qs.size() < 2) return;
  if (qs.size() <= kMostJointFeedEvents) {
    exclude(shape, f, qs, data, out, start);
    return;
  }
  for (size_t i = 0; i < qs.size(); ++i)
    for (size_t j = i + 1; j < qs.size(); ++j) exclude(shape, f, {qs[i], qs[j]}, data, out, start);
}

}  // namespace

std::string status_flag(const model::Event& event) {
  return event.flag.empty() ? event.name : event.flag;
}

void add_feed_outcomes(const model::App& app, PortShape& shape, DataQuery* data) {
  for (size_t c = 0; c < shape.connections.size(); ++c) {
    int f = static_cast<int>(c);
    const model::Connection& feed = *shape.connections[c];
    if (feed.kind != model::ConnectionKind::Feed || feed.opaque || own_delivery_feed(shape, f))
      continue;
    std::vector<size_t> qs = decided_entries(app, shape, f, data);
    std::vector<size_t> derived, lasting_until_unset;
    for (size_t q : qs) {
      Entry& e = shape.entries[q];
      e.by_message = true;
      const model::Event* event = app.find_event(e.event);
      if (event->predicate) {
        e.predicate = &*event->predicate;
        derived.push_back(q);
        if (!e.lifetime) lasting_until_unset.push_back(q);
      }
    }
    if (!data) continue;
    exclude_joint(shape, f, derived, *data, shape.excluded_outcomes, false);
    exclude_joint(shape, f, lasting_until_unset, *data, shape.excluded_at_start, true);
  }
}

// Any state (k-induction's step case): the entries of a feed's derived events without a
// lifetime show what the source's last message made them, or none of them when there was none.
void Unrolling::constrain_feeds_at_start() {
  for (const PortShape::ExcludedOutcome& x : shape_.excluded_at_start) {
    z3::expr pattern = ctx_.bool_val(true);
    for (const auto& [q, set] : x.sets) pattern = pattern && has_[0][q] == ctx_.bool_val(set);
    solver_.add(!pattern);
  }
}

}  // namespace arbc::verify::temporal
