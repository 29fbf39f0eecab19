// The DDS mediator's live status (issue 42, docs/distributed.md#live-status): what the runtime's
// port_status says, on topics any ROS 2 tool reads. Each arbitrated port mediated here has a
// latched topic (reliable, transient local, depth 1) of diagnostic_msgs/msg/DiagnosticStatus,
// written when the port's state changes, so that a subscriber that joins late reads the state
// now; /diagnostics gets a diagnostic_msgs/msg/DiagnosticArray of every port once a second of
// run time, with the counters (rqt_robot_monitor, Foxglove).
#include "dds/cdr_write.h"
#include "dds/dds_transport_internal.h"
#include "dds/status_types.h"

namespace arbc::dds {

bool DdsTransport::open_status(const TransportPlan& plan, std::string* error) {
  std::vector<std::string> ports;
  for (const model::ArbitratedPort& a : app_.arbitrated_ports) {
    for (const TransportPort& p : plan.inputs)
      if (p.mediated && p.qualified == a.port) ports.push_back(a.port);
  }
  if (ports.empty()) return true;  // nothing arbitrated here: nothing to say
  status_app_.name = "arbc_status";
  status_app_.types = status_types().named;
  status_deployment_.ros2 = true;
  status_naming_ = std::make_unique<WireNaming>(status_app_, status_deployment_);
  status_wire_ = status_naming_->port_type("arbc", "status", status_types().status, error);
  array_wire_ = status_naming_->port_type("arbc", "diagnostics", status_types().array, error);
  if (!status_wire_ || !array_wire_) return false;
  for (const std::string& port : ports) {
    auto given = options_.deployment.status_topics.find(port);
    StatusTopic s;
    s.port = port;
    s.topic = status_wire_topic(given != options_.deployment.status_topics.end()
                                    ? given->second
                                    : default_status_topic(app_.name, port));
    s.writer = status_writer(s.topic, status_wire_, /*latched=*/true, error);
    if (!s.writer) return false;
    status_topics_.push_back(std::move(s));
  }
  diagnostics_ =
      status_writer(status_wire_topic(options_.deployment.diagnostics_topic), array_wire_,
                    /*latched=*/false, error);
  return diagnostics_ != nullptr;
}

fdds::DataWriter* DdsTransport::status_writer(const std::string& topic,
                                              const std::shared_ptr<const WireType>& wire,
                                              bool latched, std::string* error) {
  fdds::Topic* t = topic_for(topic, wire, error);
  if (!t) return nullptr;
  fdds::DataWriterQos qos = publisher_->get_default_datawriter_qos();
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  // Latched as ROS 2 latches: transient local, the last sample kept for a late subscriber.
  qos.durability().kind =
      latched ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS : fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = latched ? 1 : 10;
  qos.endpoint().history_memory_policy =
      eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  std::string mark = kStatusUserData;
  qos.user_data().data_vec({mark.begin(), mark.end()});
  fdds::DataWriter* w = publisher_->create_datawriter(t, qos, nullptr, fdds::StatusMask::none());
  if (!w) *error = "DDS: cannot create the status writer on topic " + topic;
  return w;
}

void DdsTransport::publish_status(Nanos t, Nanos stamp, const std::vector<PortStatus>& ports) {
  auto write = [&](fdds::DataWriter* writer, const WireType& wire, const Value& v) {
    std::string why;
    if (cdr_write(*wire.type, v, &status_sample_.bytes, &why) && writer->write(&status_sample_))
      return;
    if (!status_failed_) {
      status_failed_ = true;
      sink_->report("DDS: the live status could not be written" +
                    (why.empty() ? std::string() : " (" + why + ")") + "; the run goes on");
    }
  };
  for (const PortStatus& p : ports) {
    for (StatusTopic& s : status_topics_) {
      if (s.port != p.port) continue;
      Value v = latched_status_value(p, app_.name);
      if (v == s.last) continue;
      write(s.writer, *status_wire_, v);
      s.last = std::move(v);
    }
  }
  if (diagnostics_at_ != -kNever && t - diagnostics_at_ < std::chrono::seconds(1)) return;
  diagnostics_at_ = t;
  write(diagnostics_, *array_wire_, diagnostic_array_value(ports, app_.name, t, stamp));
}

}  // namespace arbc::dds
