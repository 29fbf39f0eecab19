// The DDS transport as a plugin that `arbc` loads only for `arbc run --transport dds`
// (docs/distributed.md#how-arbc-finds-the-dds-transport). Loading Fast-DDS costs about as much
// start-up time as Z3, ANTLR and Lua together, so `arbc check`, `verify` and `build` must not
// pay for it. The two sides pass C++ objects, so they must come from one build: the loader
// compares the version and a layout signature and refuses a plugin that differs.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "dds/dds_transport.h"
#include "runtime/transport.h"

// The plugin's file name: beside `arbc` in a build tree, in <prefix>/lib/arbc when installed.
#define ARBC_DDS_PLUGIN_FILE "arbc_dds.so"

namespace arbc::dds {

// The version and the sizes of the objects that cross between `arbc` and the plugin, as text.
inline std::string plugin_signature() {
  return std::string(ARBC_VERSION) + "/" + std::to_string(sizeof(model::App)) + "/" +
         std::to_string(sizeof(DdsOptions)) + "/" + std::to_string(sizeof(Value)) + "/" +
         std::to_string(sizeof(TransportPlan)) + "/" + std::to_string(sizeof(Delivery));
}

}  // namespace arbc::dds

extern "C" {
// plugin_signature() as the plugin was built; the string lives as long as the plugin.
const char* arbc_dds_plugin_signature();
// make_dds_transport(*app, std::move(*options)), released to the caller.
arbc::Transport* arbc_dds_plugin_make_transport(const arbc::model::App* app,
                                                arbc::dds::DdsOptions* options);
// dds::read_status (dds/status_reader.h), for `arbc status`.
bool arbc_dds_plugin_read_status(int domain, const std::string* topic, double wait,
                                 std::vector<arbc::Value>* statuses, std::string* note,
                                 std::string* error);
}
