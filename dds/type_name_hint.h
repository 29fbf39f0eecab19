// What to do when a remote endpoint on one of this process's topics names its type otherwise
// (DDS then matches nothing between them): say where this process's name for it comes from,
// the deployment file's "types" at FILE:LINE:COL or the spec's type name, and what to write
// there to take the program's type, since the usual cause is a mapping written wrong.
#pragma once

#include <string>

#include "dds/deployment.h"

namespace arbc::dds {

// "pkg::msg::dds_::Name_" -> "pkg/msg/Name", "pkg::msg::Name" -> "pkg/msg/Name": a DDS type
// name as the deployment file's "types" writes it.
std::string deployment_type_name(const std::string& dds_name);

// The sentence that follows a type mismatch on the topic of `port` ("Module.port"), whose spec
// type is named `spec_type` ("" when the spec did not name it), when a remote endpoint uses
// `remote` (a DDS type name).
std::string type_name_hint(const Deployment& d, const std::string& port,
                           const std::string& spec_type, const std::string& remote);

}  // namespace arbc::dds
