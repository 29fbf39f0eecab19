// The DDS transport (library arbc_dds; docs/distributed.md): ports whose other end runs in
// another process travel on DDS topics through eProsima Fast-DDS 2.9.
//
//   - an output of a hosted module is published on its topic (for other mediators and any
//     DDS program), and handed to the connections from it mediated here;
//   - an output of a module hosted elsewhere that feeds connections mediated here is read from
//     its topic;
//   - what a connection mediated here delivers to a module hosted elsewhere is published on
//     that module's input topic; a hosted module whose input another process mediates reads it.
// QoS: reliable, volatile, keep-last with the deployment's depth (100 by default), or a port's
// reliability and durability from the deployment; a remote endpoint DDS does not match for its
// QoS is reported with the setting to write (dds/qos_mismatch.h). A reader
// hands samples to the executor through a buffer of that depth: its overflow counts as
// `queue-full`, samples DDS reports lost before they arrived ("sample lost": the network, a
// reordering, the writer's history) as `lost-in-transit`, and a sample that does not decode as
// `bad-type`, each with its own detail. A write while no subscriber has matched is counted as
// written to nobody and said. A remote endpoint on one of this process's topics with
// another type is reported (topic and both types) at discovery.
#pragma once

#include <memory>
#include <string>

#include "core/app_model.h"
#include "dds/deployment.h"
#include "runtime/transport.h"

namespace arbc::dds {

struct DdsOptions {
  Deployment deployment;  // topics, types, ros2, depth
  int domain = 0;         // the DDS domain (--domain, else the deployment's, else 0)
  // Wall seconds without a message from a peer participant before it counts as gone (its
  // topics' publishers are then reported lost).
  double lease_seconds = 3;
  // Wall seconds Transport::start waits for a peer on every topic that has one in the app
  // (`--wait-peers`); then the run starts anyway, naming the topics still alone. 0: no wait.
  double wait_peers = 0;
  // The run's --time-scale: run seconds per wall second (for checks timed on the wall clock).
  double time_scale = 1;
  // Wall seconds into a run after which the connected topics still without a peer are first
  // reported (a domain, topic or type unlike the programs'), then again at growing intervals
  // (dds/no_peer_reports.h); 0: never. `arbc run` takes it from ARBC_DDS_NO_PEER_AFTER when
  // set, so that tests need not wait 10 s.
  double unmatched_after = 10;
  // --use-sim-time: age() measures stamps against the last sample of /clock (dds/sim_clock.h),
  // as a ROS 2 node with use_sim_time does, not against the wall clock.
  bool use_sim_time = false;
  // The live status topics (docs/distributed.md#live-status): written unless the deployment
  // says "status": false or `arbc run --no-status-topics` this.
  bool status = true;
};

// A transport for `app` (its named types name the wire types). Nothing is created on the
// network before Transport::open.
std::unique_ptr<Transport> make_dds_transport(const model::App& app, DdsOptions options);

}  // namespace arbc::dds
