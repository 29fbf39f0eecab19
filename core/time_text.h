// A time in seconds as people read it in reports and test failures: "0.3", "2.9", "1.25".
#pragma once

#include <string>

namespace arbc {

// `t` to the microsecond, trailing zeros dropped. Simulated clocks step by sums of decimal
// periods (0.1 + 0.2 ...), whose exact binary values print as 0.30000000000000004; the
// runtime's resolution is far coarser than that noise, so a microsecond is plenty.
std::string time_text(double t);

}  // namespace arbc
