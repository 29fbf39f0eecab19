// The unit words a newcomer writes after a number (`5sec`, `0.5 s`, `0.40m`), read so that the
// error can say what to write instead: durations take ms, s or min, glued to the number, and
// plain numbers take no unit at all.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace arbc::frontend {

// The spec language's unit ("ms", "s" or "min") for a spelling of a time unit (s, sec, secs,
// second, seconds, ms, msec, millisecond(s), min, mins, minute(s)), else nothing.
std::optional<std::string> duration_unit(std::string_view word);

// `text`, a number with letters glued to it ("5sec", "0.40m"), split at its first letter:
// the digits and the rest.
std::pair<std::string, std::string> split_number_suffix(std::string_view text);

}  // namespace arbc::frontend
