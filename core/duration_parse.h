// Times as a user writes them on a command line or in an inputs file ("500ms", "60s", "2min",
// "3h"): one parser, so that every option takes the same units and says the same thing about
// a bad one (`arbc run --duration`, `arbc verify --timeout`, `arbc lsp --timeout`, `arbc run
// --wait-peers`, and the times of `arbc run --inputs`). The language's own durations are the
// front end's (compiler/frontend); this is the command line's.
#pragma once

#include <string>

namespace arbc {

// The units, and their text for messages.
inline constexpr const char* kDurationUnits = "ms, s, min or h";

// What a number without a unit means: refused (`--duration 5` could be seconds or
// milliseconds, and a run of the wrong length is a silent wrong answer), or seconds (options
// that always took a number of seconds, as their help says).
enum class BareNumber { Refused, Seconds };

// "500ms", "60s", "2min", "3h" (and "30" when `bare` is Seconds) -> seconds, finite and above
// 0 (or 0 too, with `zero_allowed`). false and `why` (a sentence about `text`, without the
// option's name) otherwise.
bool parse_duration(const std::string& text, BareNumber bare, bool zero_allowed, double* seconds,
                    std::string* why);

}  // namespace arbc
