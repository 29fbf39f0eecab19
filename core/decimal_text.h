// A double as the shortest decimal that reads back as it, written without an exponent
// ("0.00005", not "5e-05"): the decimal a person (or arbc) wrote when the double came from one,
// 0.1 rather than the double's 0.1000000000000000055... core/instant.h reads a duration given
// as a double through it; it is also the one form of a number that Z3 4.8's real_val reads
// exactly (it read "5e-05" as (/ 1.0 0.0), an unknown real, and "1e+15" as 0).
#pragma once

#include <string>

namespace arbc {

// `v` finite; "-0.25", "3", "0.0000000005", "1000000000000000".
std::string shortest_decimal(double v);

}  // namespace arbc
