// `arbc run`'s transport options (docs/distributed.md):
//   --transport inproc|dds  --host M1,M2|all|none  --mediate M1,M2|all|none  --deploy FILE
//   --domain N  --time-scale K  --wait-peers S
// `inproc` (the default) runs everything in this process on simulated time (or the wall clock
// with --realtime). `dds` runs the hosted modules and the connections into the mediated ones
// on the wall clock scaled by K, and exchanges the rest over DDS topics.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/runtime.h"

namespace arbc::cli {

struct TransportFlags {
  std::string transport = "inproc";
  std::string host, mediate;  // empty: all, and the hosted modules
  std::string deploy;
  std::vector<std::string> msg_path;  // --msg-path: folders of PKG/msg/NAME.msg
  std::optional<int> domain;
  std::optional<double> time_scale;
  std::optional<double> wait_peers;
  bool use_sim_time = false;      // dds: age() reads /clock (dds/sim_clock.h)
  bool no_status_topics = false;  // dds: no live status topics (dds/status_types.h)
};

void add_transport_options(CLI::App& cli, TransportFlags* flags);

// The DDS domain: --domain (`flag`), else the deployment file's, else ROS 2's ROS_DOMAIN_ID,
// else 0. A ROS_DOMAIN_ID that is not a domain is refused, not read as 0 (atoi's answer): a
// mediator in another domain than its programs would hear nothing and say nothing. False with
// *error (what is wrong, what to do) when it is not a domain.
bool choose_domain(std::optional<int> flag, std::optional<int> file, int* domain,
                   std::string* error);

// Checks the flags against the app and sets options' placement, clock and transport (a DDS
// transport for `dds`). Returns an exit code (kExitOk, or kExitBadInput after printing what
// is wrong).
int apply_transport(const TransportFlags& flags, const model::App& app, RunOptions* options);

// "dds (domain 7, time scale 10, hosts all, mediates none)" for the run's header line; "" for
// an in-process run.
std::string describe_transport(const TransportFlags& flags, const RunOptions& options);

}  // namespace arbc::cli
