// The Bottle layout of spec values (docs/yarp.md#the-bottle-layout), in C++ for the replay
// test: the generated monitors implement it in Lua (compiler/codegen/yarp_bottle_lua.h), and
// this second implementation is what they are checked against.
#pragma once

#include <yarp/os/Bottle.h>

#include <nlohmann/json.hpp>

#include "core/type.h"

namespace arbc::yarp_test {

// Fills `b` with `value` (a trace's JSON value) of type `t`.
void write_value(::yarp::os::Bottle& b, const nlohmann::json& value, const Type& t);

}  // namespace arbc::yarp_test
