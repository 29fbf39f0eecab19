// A double as the shortest decimal that reads back as it, written without an exponent
// ("0.00005", not "5e-05"): the one form of a number that Z3 4.8's real_val reads exactly. It
// reads "5e-05" as (/ 1.0 0.0), an unknown real, and "1e+15" as 0, so a duration below 100 us
// or of 1e15 s and more meant something else in the proof than in the runtime (a hold of
// 0.0000000005s even crashed Z3 with a division by zero).
#pragma once

#include <string>

namespace arbc::verify::temporal {

// `v` finite; "-0.25", "3", "0.0000000005", "1000000000000000".
std::string shortest_decimal(double v);

}  // namespace arbc::verify::temporal
