// An example Bottle of a spec type in the layout the generated YARP monitors read
// (docs/yarp.md#the-bottle-layout), as Bottle text: what a module must write. A monitor that
// drops a message without the layout quotes it, so the module's author sees the difference.
#pragma once

#include <string>

#include "core/type.h"

namespace arbc::codegen {

// The Bottle text of a message of type `t` holding zeros, empty strings and one element per
// list: `(vx 0.0) (wz 0.0)` for {vx: float, wz: float}, `0.0 0.0 0.0` for a vec3.
std::string yarp_layout_example(const Type& t);

}  // namespace arbc::codegen
