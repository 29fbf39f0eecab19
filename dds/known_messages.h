// The fields, in order, of the ROS 2 messages that spec records most often stand for. Nothing
// on the wire names a field: a spec record that lists a message's fields in another order
// decodes without error when the fields have the same types (a Twist's `linear` and `angular`
// are both Vector3), and every rule then reads one field for another. Where the deployment
// maps a spec type to one of these messages, that order is checked before anything runs.
#pragma once

#include <string>

#include "core/type.h"

namespace arbc::dds {

// What is wrong with record `spec` (the spec's type `name`) standing for `message`
// ("geometry_msgs/msg/Twist", or its DDS name), when it has the message's field names in
// another order, here or in a field that is itself a known message; "" when the order is
// right, the names are not the message's, or the message is not one of those known.
std::string field_order_problem(const std::string& name, const Type& spec,
                                const std::string& message);

}  // namespace arbc::dds
