// Where the tests find the checkout (specs, goldens, docs) and the build tree (the arbc binary,
// scratch files).
#pragma once

#include <string>

namespace arbc::testing {

// The checkout's root directory, absolute.
const std::string& source_dir();
// The build tree's root directory, absolute.
const std::string& binary_dir();

}  // namespace arbc::testing
