#include "dds/status_reader.h"

#include <chrono>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <map>
#include <thread>

#include "dds/participant_qos.h"
#include "dds/status_types.h"
#include "dds/topic_type.h"

namespace arbc::dds {

namespace {

namespace fdds = eprosima::fastdds::dds;
using ReturnCode_t = eprosima::fastrtps::types::ReturnCode_t;

// The statuses of `array` that an arbc mediator wrote, into *last by name.
void keep_arbc_statuses(const Value& array, std::map<std::string, Value>* last) {
  for (const Value& s : array["status"].as_list()) {
    const Value& first = s["values"][size_t{0}];
    if (first["key"].as_string() == "selected") (*last)[s["name"].as_string()] = s;
  }
}

// Takes every sample `reader` has; false when DDS said no sample.
bool take_all(fdds::DataReader* reader, WireSample* sample, std::map<std::string, Value>* last) {
  fdds::SampleInfo info;
  bool any = false;
  while (reader->take_next_sample(sample, &info) == ReturnCode_t::RETCODE_OK) {
    any = true;
    if (info.valid_data && !sample->bad) keep_arbc_statuses(sample->value, last);
  }
  return any;
}

}  // namespace

bool read_status(int domain, const std::string& topic, double wait, std::vector<Value>* statuses,
                 std::string* note, std::string* error) {
  fdds::DomainParticipantQos qos;
  if (!participant_qos({"arbc status", domain, 3}, &qos, note, error)) return false;
  fdds::DomainParticipantFactory* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipant* p = factory->create_participant(domain, qos);
  if (!p) {
    *error = "DDS: cannot create a participant in domain " + std::to_string(domain);
    return false;
  }
  // The type as the mediators write it (dds_status.cc): ROS 2 names, whatever a deployment says.
  model::App names;
  names.types = status_types().named;
  Deployment ros2;
  ros2.ros2 = true;
  WireNaming naming(names, ros2);
  std::shared_ptr<const WireType> wire =
      naming.port_type("arbc", "diagnostics", status_types().array, error);
  std::map<std::string, Value> last;
  if (wire) {
    fdds::TypeSupport support(new WireTopicType(wire));
    support.register_type(p);
    std::string wire_topic = status_wire_topic(topic);
    fdds::Topic* t = p->create_topic(wire_topic, wire->name, fdds::TOPIC_QOS_DEFAULT);
    fdds::Subscriber* sub = p->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
    fdds::DataReaderQos rq = sub->get_default_datareader_qos();
    rq.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    fdds::DataReader* reader = t && sub ? sub->create_datareader(t, rq) : nullptr;
    if (!reader) *error = "DDS: cannot read topic " + wire_topic;
    auto* sample = static_cast<WireSample*>(support->createData());
    auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait);
    while (reader && std::chrono::steady_clock::now() < until) {
      if (!take_all(reader, sample, &last))
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    support->deleteData(sample);
    if (!reader) wire.reset();
  }
  p->delete_contained_entities();
  factory->delete_participant(p);
  for (auto& [name, s] : last) statuses->push_back(std::move(s));
  return wire != nullptr;
}

}  // namespace arbc::dds
