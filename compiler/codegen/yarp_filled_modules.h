// The <module> elements a user filled in (docs/yarp.md#deploying-a-spec-on-yarp-step-by-step,
// step 3: the executable, its parameters, its node) survive a rebuild: `arbc build --target
// yarp` replaces the application directory as a whole, and the spec does not know them.
#pragma once

#include <string>
#include <vector>

namespace arbc::codegen {

// `generated` with each placeholder <module> of a spec module replaced by that module's
// <module> element in `previous` (the application XML of the build being replaced) when the
// user changed it there. A module is found in `previous` by the comment arbc writes above it
// (`<!-- NAME: ...` or `<!-- NAME. ...`). The names of the modules kept go to `kept`, those of
// filled-in modules the spec no longer has (not carried over) to `dropped`.
std::string keep_filled_modules(const std::string& generated, const std::string& previous,
                                std::vector<std::string>* kept, std::vector<std::string>* dropped);

}  // namespace arbc::codegen
