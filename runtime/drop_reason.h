// Why a message did not reach its destination (docs/design.md#the-message-path: no message
// disappears silently). The names are the trace's "reason" field and the counters' column names.
#pragma once

namespace arbc {

enum class DropReason {
  Rejected,      // accept returned false
  NoValue,       // an expression had no value (PortMonitor.novalue())
  NotSelected,   // the connection's constraint was false on the container
  Throttled,     // a delivery happened less than the throttle period ago
  Feed,          // consumed by a feed connection (constraint false by design)
  MonitorError,  // a script error or a callback returned the wrong type
  Quarantined,   // the connection failed too often and was taken out of service
  QueueFull,     // the connection's queue was at its bound
  BadType,       // the source module published a value its output port's type does not admit
};
inline constexpr int kDropReasonCount = 9;

inline const char* drop_reason_name(DropReason r) {
  switch (r) {
    case DropReason::Rejected:
      return "rejected";
    case DropReason::NoValue:
      return "no-value";
    case DropReason::NotSelected:
      return "not-selected";
    case DropReason::Throttled:
      return "throttled";
    case DropReason::Feed:
      return "feed";
    case DropReason::MonitorError:
      return "monitor-error";
    case DropReason::Quarantined:
      return "quarantined";
    case DropReason::QueueFull:
      return "queue-full";
    case DropReason::BadType:
      return "bad-type";
  }
  return "?";
}

}  // namespace arbc
