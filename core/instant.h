// Instants and durations of a run as whole nanoseconds (docs/design.md#events-and-lifetimes).
//
// The proof reads every duration as an exact decimal, and a spacing it proves over real times
// ("less than 1s after the last one" never happens) is a claim about every pair of instants the
// runtime can produce. With run times in doubles that claim failed twice over: 0.2 + 0.1 > 0.3,
// and the tolerance that fixed it (instants within 1 ns of a deadline counted as the deadline)
// let a `throttle 1s` pass two deliveries 0.9999999995 s apart. So every instant the runtime
// decides with (the executor's clock and tasks, expiries, throttles, holds, trig intervals) is an
// integer count of nanoseconds since the run's start, compared exactly (`now >= deadline`), and
// every duration of a spec or an app.json is a whole number of nanoseconds, which the proof reads
// as that integer over 1e9: a spacing that holds over the reals holds on that grid.
//
// Doubles remain at the edges people and modules see (the module API, Lua's PortMonitor.now(),
// setEvent's lifetime, a trace read back): they cross into the runtime through
// nanos_from_seconds alone, which rounds to the nearest nanosecond, so two doubles that round to
// the same nanosecond are one instant.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace arbc {

// An instant (since the run's start) or a duration. std::chrono's type rather than a bare
// int64_t: a double of seconds does not convert to it silently.
using Nanos = std::chrono::nanoseconds;

// No deadline: an entry without a lifetime, a task that never runs.
inline constexpr Nanos kNever = Nanos::max();

// The longest duration a spec or an app.json may state, and the latest instant a run reaches
// (about 100 years): an instant plus a duration then never overflows 64 bits.
inline constexpr Nanos kLongestDuration = std::chrono::hours(24 * 36525);

// `seconds` (a module's delay, Lua's lifetime, a time read from a trace) to the nearest
// nanosecond, halves away from zero; beyond +-kNever saturated, NaN is 0. The one conversion
// from a double into the runtime's instants.
Nanos nanos_from_seconds(double seconds);

// `t` in seconds as a double (the module API's and Lua's unit): the double nearest t / 1e9,
// so 300 ms reads 0.3, as written, and not 0.30000000000000004.
inline double seconds_of(Nanos t) { return static_cast<double>(t.count()) / 1e9; }

// `t` in seconds as an exact decimal without an exponent ("0.3", "2", "1.000000001",
// "-0.25"): how traces, app.json and the proof write an instant or a duration.
std::string decimal_seconds(Nanos t);

// The whole nanoseconds the decimal `digits` ("1.5", "12", no sign, no exponent) times a
// unit of `unit` nanoseconds mean (1e9 for s, 1e6 for ms, 6e10 for min); nullopt when that is
// not a whole number of nanoseconds or is longer than kLongestDuration. Exact: the text is
// never read as a double.
std::optional<Nanos> nanos_of_decimal(std::string_view digits, int64_t unit);

// The whole nanoseconds `seconds` means as the shortest decimal that reads back as it (what a
// person or arbc wrote: 0.1 is 100 ms, not the double's 0.1000000000000000055...); nullopt
// when that decimal has more than 9 digits after the point (0.1234567891, 1.0 / 3), is negative
// or not finite, or is longer than kLongestDuration.
std::optional<Nanos> whole_nanos(double seconds);

// `t + d` for d >= 0, kNever when that would pass kNever (a module's timer far in the future).
inline Nanos later(Nanos t, Nanos d) { return t > kNever - d ? kNever : t + d; }

}  // namespace arbc
