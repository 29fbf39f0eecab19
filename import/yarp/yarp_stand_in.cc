#include "import/yarp/yarp_stand_in.h"

namespace arbc::embedded {
extern const std::string_view kYarpStandInLua;  // yarp_stand_in.lua, embedded at build time
}  // namespace arbc::embedded

namespace arbc::yarp {

std::string_view yarp_stand_in_source() { return embedded::kYarpStandInLua; }

}  // namespace arbc::yarp
