// Why a message did not reach its destination (docs/design.md#the-message-path: no message
// disappears silently). The names are the trace's "reason" field, the counters' column names
// and what `expect RULE drops "reason"` accepts. kDropReasons is the one table of the closed
// set: a new reason is a row there (and a line in docs/runtime.md#drop-reasons), and every
// table, legend and check that lists them reads it.
#pragma once

#include <iterator>

namespace arbc {

enum class DropReason {
  Rejected,
  NoValue,
  NotSelected,
  Throttled,
  Feed,
  MonitorError,
  Quarantined,
  QueueFull,
  BadType,
  LostInTransit,
  BadValue,
};

struct DropReasonInfo {
  DropReason reason;
  const char* name;     // the trace's and the table's word
  const char* meaning;  // for the run report's table
  const char* color;    // the run report's swatch and timeline mark
  // A loss (the message never reached the connection's judgement, or the transport lost it),
  // as opposed to a judgement that says no by design (not selected, throttled, ...); losses
  // in bulk are said when they start (RunOptions::report_bulk_drops).
  bool loss;
};

// In the order of DropReason, which is the order of the end-of-run table's columns.
inline constexpr DropReasonInfo kDropReasons[] = {
    {DropReason::Rejected, "rejected", "the monitor's accept returned false", "#e69f00", false},
    {DropReason::NoValue, "no-value",
     "an expression had no value (min_by of an empty list, an index out of range)", "#cc79a7",
     false},
    {DropReason::NotSelected, "not-selected",
     "the connection's constraint was false on the port's events", "#7f7f7f", false},
    {DropReason::Throttled, "throttled",
     "a delivery on this connection less than its throttle period ago", "#56b4e9", false},
    {DropReason::Feed, "feed",
     "consumed by an event feed (by design: feeds set events, never deliver)", "#c8c8c8", false},
    {DropReason::MonitorError, "monitor-error",
     "a script error, the instruction budget, the memory cap or a wrong return type", "#d55e00",
     true},
    {DropReason::Quarantined, "quarantined", "the connection had been taken out of service",
     "#7a0000", true},
    {DropReason::QueueFull, "queue-full",
     "this process's queue was at its bound: the connection's, or a DDS reader's", "#9467bd", true},
    {DropReason::BadType, "bad-type",
     "the source published a value its output port's type does not admit, or a DDS sample that "
     "does not decode as that type",
     "#8c564b", true},
    {DropReason::LostInTransit, "lost-in-transit",
     "DDS reported the sample lost before it reached this process: the network lost or "
     "reordered it, or the writer dropped it",
     "#17becf", true},
    {DropReason::BadValue, "bad-value",
     "a value the rule's proof excluded (a list longer than the --list-bound its proof needed)",
     "#bcbd22", true},
};
inline constexpr int kDropReasonCount = static_cast<int>(std::size(kDropReasons));

constexpr bool drop_reasons_in_order() {
  for (int i = 0; i < kDropReasonCount; ++i) {
    if (static_cast<int>(kDropReasons[i].reason) != i) return false;
  }
  return true;
}
static_assert(drop_reasons_in_order(), "kDropReasons lists DropReason in its order");

inline const DropReasonInfo& drop_reason_info(DropReason r) {
  return kDropReasons[static_cast<int>(r)];
}
inline const char* drop_reason_name(DropReason r) { return drop_reason_info(r).name; }

}  // namespace arbc
