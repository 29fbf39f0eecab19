// Values <-> Fast-DDS dynamic data of a port's wire type (dds/wire_types.h). The mediator reads
// and writes samples' bytes itself (dds/cdr_read.h, dds/cdr_write.h); these are Fast-DDS's own
// path, which the tests hold those to.
#pragma once

#include <fastrtps/types/DynamicData.h>

#include <string>

#include "core/value.h"
#include "dds/wire_types.h"

namespace arbc::dds {

// Fills `data` (created for w.dynamic) with v, which conforms to w.type. False with *error
// when Fast-DDS refuses a value.
bool to_wire(const WireType& w, const Value& v, eprosima::fastrtps::types::DynamicData* data,
             std::string* error);
// The value `data` holds; false with *error when a member cannot be read (a sample that
// decoded into another structure).
bool from_wire(const WireType& w, eprosima::fastrtps::types::DynamicData* data, Value* out,
               std::string* error);

}  // namespace arbc::dds
