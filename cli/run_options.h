// Parsing of `arbc run`'s values that CLI11 would accept too loosely (docs/cli.md, `arbc run`):
// a duration needs its unit, a seed is a whole number that does not wrap.
#pragma once

#include <cstdint>
#include <string>

namespace arbc::cli {

// The longest run: 30 days. Times are seconds in a double, whose resolution is 0.5 ns at 30
// days and passes the 1 ns tolerance of core/instant.h at 2^22 s (48 days); `--duration 1e12h`
// was accepted and ran until killed.
inline constexpr double kMaxRunSeconds = 30 * 24 * 3600.0;

// --duration: "60s", "500ms", "2min", "3h" -> seconds (> 0, at most kMaxRunSeconds), by
// parse_duration (duration_option.h); a number without a unit is refused.
bool parse_run_duration(const std::string& text, double* seconds, std::string* err);

// "0" .. "18446744073709551615" -> the seed. A sign, a fraction or an overflow is refused
// (CLI11 would turn "-1" into 2^64 - 1).
bool parse_seed(const std::string& text, uint64_t* seed, std::string* err);

}  // namespace arbc::cli
