// The transport seam (docs/design.md#transports): where the messages of the modules hosted in
// this process go, and where the messages for the connections mediated here come from.
//
// The engine (monitors, event containers, arbitrators, executor) calls a Transport and is
// called back through a TransportSink; it never knows whether a message crossed a process.
//   - A hosted module publishes: Runtime -> Transport::publish(out) -> (here or elsewhere)
//     TransportSink::from_source(out) -> the connections from `out` mediated here.
//   - A mediated connection delivers: Runtime -> Transport::deliver(in) -> (here or elsewhere)
//     TransportSink::to_module(in) -> the hosted module's on_delivery.
// The in-process transport (make_inproc_transport) routes both calls straight back to the
// sink: today's single-process behaviour. The DDS transport (dds/, library arbc_dds) routes
// ports whose other end runs in another process through DDS topics.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/instant.h"
#include "core/type.h"
#include "core/value.h"
#include "runtime/drop_reason.h"
#include "runtime/module.h"
#include "runtime/port_status.h"
#include "runtime/transport_status.h"

namespace arbc {

class Executor;

// A set of module names, or all of them (`--host`, `--mediate`).
struct ModuleSet {
  bool all = true;
  std::set<std::string, std::less<>> names;

  static ModuleSet everything() { return {}; }
  static ModuleSet none() { return {false, {}}; }
  bool contains(std::string_view module) const { return all || names.count(module) > 0; }
  bool empty() const { return !all && names.empty(); }
};

// One port of the app as a transport sees it.
struct TransportPort {
  int index = 0;  // the runtime's number for the port, passed back in every call
  std::string module, port, qualified;  // qualified: "Module.port"
  TypePtr type;
  bool hosted = false;  // its module runs in this process
  // Input: the connections into it run here. Output: some connection from it runs here.
  bool mediated = false;
  // Output mediated here: the connections it reaches here ("pendant into Gripper.cmd"; feeds
  // left out) and the events their monitors set, so that a transport can say what the output's
  // silence does.
  std::vector<std::string> connections, events;
};

// Every port of the app, outputs and inputs each indexed by TransportPort::index.
struct TransportPlan {
  std::string app;
  std::vector<TransportPort> outputs, inputs;
};

// The engine's side of the seam. Transports call it on the executor's thread only.
class TransportSink {
 public:
  virtual ~TransportSink() = default;
  // A message published on output `out`, for the connections from it mediated here.
  // `answered`: how many of this process's deliveries into the module of `out` (one hosted
  // elsewhere) that module had received when it published the message, counted in the order
  // Transport::deliver was called (docs/design.md#deliveries-not-yet-answered); kAnswersAll
  // for a module hosted here.
  static constexpr uint64_t kAnswersAll = UINT64_MAX;
  virtual void from_source(int out, const Value& v, uint64_t answered) = 0;
  // A message mediated for input `in` of a module hosted here.
  virtual void to_module(int in, const Delivery& d) = 0;
  // `count` messages for a port were lost before the engine saw them (a transport's queue
  // overflowed: queue-full; a sample could not be decoded: bad-type; the transport reports
  // them lost on the way: lost-in-transit), all with the one `detail`. `input` tells whether
  // `index` is an input (a hosted module's port) or an output (a source of mediated
  // connections, each of which counts the loss).
  virtual void lost(bool input, int index, DropReason reason, uint64_t count,
                    const std::string& detail) = 0;
  // A line for the run's log (stderr) and the trace.
  virtual void report(const std::string& line) = 0;
  virtual Executor& executor() = 0;
};

class Transport {
 public:
  virtual ~Transport() = default;
  virtual std::string name() const = 0;
  // Once, when the runtime is built: sets up what the plan needs (DDS: participant, topics,
  // readers, writers). False with *error when it cannot; nothing is exchanged yet.
  virtual bool open(const TransportPlan& plan, TransportSink* sink, std::string* error) = 0;
  // Messages may flow from now on (called first by Runtime::start, before the modules and the
  // environment start). A transport may wait here for its peers; it returns early once
  // *interrupt (when not null) is true.
  virtual void start(const std::atomic<bool>* interrupt) {}
  // A module hosted here published `v` on output `out` (v conforms to the port's type).
  virtual void publish(int out, const Value& v) = 0;
  // A connection mediated here delivers `d` into input `in`.
  virtual void deliver(int in, const Delivery& d) = 0;
  // Stops exchanging and releases what open() created (Runtime::shutdown, and the runtime's
  // destructor when the run never ended); a second call does nothing.
  virtual void close() {}
  // Lines about the transport for the end of the run (peers seen and lost, ...); may be empty.
  virtual std::string summary() const { return {}; }
  // The same as data, for the run's report; empty when nothing crosses a process.
  virtual TransportStatus status() const { return {}; }
  // True when publish(out, v) is exactly sink->from_source(out, v, kAnswersAll) and
  // deliver(in, d) exactly sink->to_module(in, d), on the caller's thread (the in-process
  // transport): the runtime then makes those calls itself, two indirect calls fewer per hop.
  virtual bool loops_back() const { return false; }
  // ROS 2 time read from the network, when the run takes its time from there (DDS with
  // --use-sim-time: the last /clock sample), for age(); nullopt: the executor's clock
  // (Executor::stamp_origin). Called from the runtime's thread, while a message is judged.
  virtual std::optional<Nanos> ros_time() const { return std::nullopt; }
  // The live status of the arbitrated ports mediated here (runtime/port_status.h) at run time
  // `t` (`stamp`: its ROS 2 time), every RunOptions::status_period: a transport that carries it
  // writes it (DDS: each port's latched status topic and /diagnostics). carries_status: whether
  // it does (after open), so that the runtime takes the status only then.
  virtual bool carries_status() const { return false; }
  virtual void publish_status(Nanos t, Nanos stamp, const std::vector<PortStatus>& ports) {}
};

// Today's behaviour: every module hosted and mediated in this one process; publish and deliver
// go straight back to the sink. open() refuses a plan with a port not hosted or not mediated.
std::unique_ptr<Transport> make_inproc_transport();

}  // namespace arbc
