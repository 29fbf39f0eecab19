// Loads the DDS transport plugin (dds/transport_plugin.h) for `arbc run --transport dds`.
#pragma once

#include <memory>
#include <string>

#include "core/app_model.h"
#include "dds/dds_transport.h"
#include "runtime/transport.h"

namespace arbc::cli {

// The DDS transport for `app`, from arbc_dds.so beside this executable (a build tree) or in
// ../lib/arbc (an installation); nullptr and *err, saying where it looked, when the plugin is
// missing, does not load or comes from another build.
std::unique_ptr<Transport> load_dds_transport(const model::App& app, dds::DdsOptions options,
                                              std::string* err);

// dds::read_status (dds/status_reader.h) through the same plugin: the statuses the mediators of
// `domain` write on `topic` within `wait` wall seconds, and a note on the participant's set-up
// (or empty). False and *err when the plugin cannot be loaded or DDS cannot be set up.
bool read_dds_status(int domain, const std::string& topic, double wait,
                     std::vector<Value>* statuses, std::string* note, std::string* err);

}  // namespace arbc::cli
