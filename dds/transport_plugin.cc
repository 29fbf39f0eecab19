#include "dds/transport_plugin.h"

#include <utility>

#include "dds/status_reader.h"

extern "C" {

__attribute__((visibility("default"))) const char* arbc_dds_plugin_signature() {
  static const std::string signature = arbc::dds::plugin_signature();
  return signature.c_str();
}

__attribute__((visibility("default"))) arbc::Transport* arbc_dds_plugin_make_transport(
    const arbc::model::App* app, arbc::dds::DdsOptions* options) {
  return arbc::dds::make_dds_transport(*app, std::move(*options)).release();
}

__attribute__((visibility("default"))) bool arbc_dds_plugin_read_status(
    int domain, const std::string* topic, double wait, std::vector<arbc::Value>* statuses,
    std::string* note, std::string* error) {
  return arbc::dds::read_status(domain, *topic, wait, statuses, note, error);
}
}
