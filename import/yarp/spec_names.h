// How YARP's names become spec names in `arbc import yarp` (docs/yarp.md#moving-to-a-spec):
// anything YARP accepts as a port name or connection id, a spec name cannot always hold. Two
// YARP names that become one spec name are told apart (`_2`, `_3`, ...), each with a warning
// yarp-spec-name that says which YARP name became which spec name: merged, two modules would
// be one, and two rules of one name are an error of `arbc check`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "import/yarp/yarp_import.h"

namespace arbc::yarp {

// A spec name for any text: letters, digits and '_' (other characters become '_', those at
// either end are dropped), not starting with a digit (`p_` is put before), no keyword (`_` is
// put after).
std::string identifier(const std::string& text);

// The spec name of each connection's rule, parallel to im.app.connections: identifier() of
// the model's name, made unique among the rules into one port. The model's names are unique
// already (yarp-duplicate-id), but two of them can become one spec name (`track-ball` and
// `track_ball` are both `track_ball`): the later one is renamed.
std::vector<std::string> spec_rule_names(const YarpImport& im, std::vector<Diagnostic>& renamed);

// A YARP port as a spec port: `/a/b:o` is `a.b_o`, the part before the last '/' its module.
struct SpecPort {
  std::string module, port;
  bool out = false;  // a source of some connection
};

// Every port the connections name, by YARP name. Each YARP module (the part of a port name
// before its last '/') is one spec module, and each spec module one YARP module: `/a-b/x` and
// `/a_b/y` are in the modules `a_b` and `a_b_2`, not both in `a_b`. Likewise each port of a
// module has its own name there. The later name is the renamed one (sources first, then
// destinations, in the connections' order).
std::map<std::string, SpecPort> spec_port_names(const YarpImport& im,
                                                std::vector<Diagnostic>& renamed);

}  // namespace arbc::yarp
