#include "dds/transport_plugin.h"

#include <utility>

extern "C" {

__attribute__((visibility("default"))) const char* arbc_dds_plugin_signature() {
  static const std::string signature = arbc::dds::plugin_signature();
  return signature.c_str();
}

__attribute__((visibility("default"))) arbc::Transport* arbc_dds_plugin_make_transport(
    const arbc::model::App* app, arbc::dds::DdsOptions* options) {
  return arbc::dds::make_dds_transport(*app, std::move(*options)).release();
}
}
