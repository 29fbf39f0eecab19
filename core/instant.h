// Run times are doubles; the proof's times are exact reals (docs/design.md#events-and-lifetimes).
// In doubles 0.2 + 0.1 > 0.3, so an event set at 0.2 s for 0.1 s would still be present at
// 0.3 s, and a rule throttled for 0.1 s after a delivery at 0.2 s would still be throttled:
// the runtime would disagree with the proof (and with the person who wrote the times) at
// exactly the instants where a counterexample over time tends to sit. So comparisons of a time
// with a deadline treat instants closer than this as one instant.
#pragma once

namespace arbc {

inline constexpr double kSameInstant = 1e-9;  // seconds

// The shortest duration a spec or an app.json may state (a lifetime, hold, throttle, period,
// window). The proof reads durations as exact reals, but the runtime takes a lifetime of
// kSameInstant or less as over the instant it is set: a hold of 0.0000000005s let the rule below
// deliver at the very instant the proof said the hold kept it out. Counterexamples are replayed
// on a grid of microseconds, so the bound is one microsecond.
inline constexpr double kShortestDuration = 1e-6;  // seconds

// Whether `now` has reached `deadline` (a lapse, the end of a throttle period).
inline bool reached(double now, double deadline) { return now + kSameInstant >= deadline; }

}  // namespace arbc
