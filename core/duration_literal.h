// A time as the spec language writes a duration literal: "0s", "100ms", "0.5ms", "1.2s", so
// that what `arbc test` says about a run reads like the expectation it quotes and can be
// copied into a test (`at 100ms`, not `at 0.1s` beside `at 100ms`).
#pragma once

#include <string>

#include "core/instant.h"

namespace arbc {

// `t` exactly: in ms below a second, in s from a second on (trailing zeros dropped), so
// "0.000001ms" is a nanosecond and "1.000000001s" a nanosecond past a second; 0 is "0s", as tests
// write their start. An instant of a run or a duration of the model, which are whole
// nanoseconds (core/instant.h), reads back as the same integer.
std::string duration_literal(Nanos t);

// A time that is not one of a run's instants (a wall-clock budget, a wait measured on the host)
// to the microsecond, in the same form.
std::string duration_literal(double seconds);

// An age in a live view (`arbc run --status`, the DDS status): to the millisecond, rounded
// down; a view refreshed four times a second has no use for a run's nanoseconds.
std::string age_literal(Nanos age);

}  // namespace arbc
