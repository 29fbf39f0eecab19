// The Bottle layout of spec values on YARP (docs/yarp.md#the-bottle-layout), as Lua that YARP
// monitors include: reading a message's Bottle into the value the spec's code sees, and writing
// the delivered value back. Reading returns nil for a Bottle without the layout; neither raises
// on a value of the declared type.
//
//   bool        an int, 1 or 0            vec3     three floats: x y z
//   int         an int (32 or 64 bits)    list<T>  the elements, each as below
//   float       a float64                 record   one (name value) pair per field
//   string      a string
//
// A message is the Bottle of its value's elements (a vec3 message is `x y z`, a scalar message
// one element); nested inside a list or record, a vec3, list or record is a sublist.
#pragma once

#include <string>

#include "core/type.h"

namespace arbc::codegen {

// The functions arbc_read(thing, T) and arbc_write(bottle, value, T), as Lua source.
std::string yarp_bottle_lua();

// A Lua table describing type `t` for those functions.
std::string yarp_type_descriptor(const Type& t);

}  // namespace arbc::codegen
