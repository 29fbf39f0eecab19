// Which arbc binary is running: the GNU build id the linker wrote into it (a digest of the
// binary's contents), so that a proof recorded by one arbc is trusted only by the same binary.
#pragma once

#include <string>

namespace arbc::verify {

// The running executable's build id in lower-case hexadecimal, or "" when it has none (a
// linker without --build-id): then no recorded proof is trusted.
std::string executable_build_id();

}  // namespace arbc::verify
