// A time as the spec language writes a duration literal: "0s", "100ms", "0.5ms", "1.2s", so
// that what `arbc test` says about a run reads like the expectation it quotes and can be
// copied into a test (`at 100ms`, not `at 0.1s` beside `at 100ms`).
#pragma once

#include <string>

namespace arbc {

// `seconds` to the microsecond: in ms below a second, in s from a second on (trailing zeros
// dropped); 0 is "0s", as tests write their start.
std::string duration_literal(double seconds);

}  // namespace arbc
