#include "dds/sim_clock.h"

#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include "core/type.h"
#include "dds/topic_type.h"

namespace arbc::dds {

namespace fdds = eprosima::fastdds::dds;
namespace ft = eprosima::fastrtps::types;
using eprosima::fastrtps::types::ReturnCode_t;

namespace {

const char* kTopic = "rt/clock";
const char* kClockName = "rosgraph_msgs::msg::dds_::Clock_";

// rosgraph_msgs/msg/Clock: `builtin_interfaces/Time clock`, under ROS 2's wire names.
std::shared_ptr<const WireType> clock_wire_type() {
  ft::DynamicTypeBuilderFactory* f = ft::DynamicTypeBuilderFactory::get_instance();
  ft::DynamicTypeBuilder_ptr time(f->create_struct_builder());
  time->set_name("builtin_interfaces::msg::dds_::Time_");
  time->add_member(0, "sec", f->create_int32_type());
  time->add_member(1, "nanosec", f->create_uint32_type());
  ft::DynamicTypeBuilder_ptr clock(f->create_struct_builder());
  clock->set_name(kClockName);
  clock->add_member(0, "clock", time->build());
  auto wire = std::make_shared<WireType>();
  wire->name = kClockName;
  wire->dynamic = clock->build();
  wire->type = parse_type("{clock: {sec: int32, nanosec: uint32}}");
  wire->signature = "Clock{clock: {sec: int32, nanosec: uint32}}";
  return wire;
}

}  // namespace

bool SimClock::open(fdds::DomainParticipant* participant, fdds::Subscriber* subscriber,
                    std::string* error) {
  if (participant->find_type(kClockName)) {
    *error = std::string(
                 "DDS: --use-sim-time reads rt/clock itself, but a port of the app has "
                 "its type (") +
             kClockName + "): leave /clock out of the app, or run without --use-sim-time";
    return false;
  }
  type_ = fdds::TypeSupport(new WireTopicType(clock_wire_type()));
  if (type_.register_type(participant) != ReturnCode_t::RETCODE_OK) {
    *error = std::string("DDS: cannot register type ") + kClockName + " for --use-sim-time";
    return false;
  }
  fdds::Topic* topic = participant->create_topic(kTopic, kClockName, fdds::TOPIC_QOS_DEFAULT);
  fdds::DataReaderQos qos = subscriber->get_default_datareader_qos();
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  reader_ = topic ? subscriber->create_datareader(topic, qos, this) : nullptr;
  if (!reader_) {
    *error = std::string("DDS: cannot read ") + kTopic + " (" + kClockName +
             ") for --use-sim-time (Fast-DDS said why above)";
    return false;
  }
  return true;
}

void SimClock::close() {
  if (reader_) reader_->set_listener(nullptr);
  reader_ = nullptr;
}

// On a DDS thread: each valid sample's time, stored for the runtime's thread to read.
void SimClock::on_data_available(fdds::DataReader* reader) {
  auto* sample = static_cast<WireSample*>(type_.create_data());
  fdds::SampleInfo info;
  while (reader->take_next_sample(sample, &info) == ReturnCode_t::RETCODE_OK) {
    if (!info.valid_data || sample->bad) continue;
    const Value& t = sample->value["clock"];
    ns_.store(t["sec"].as_int() * 1000000000 + t["nanosec"].as_int(), std::memory_order_release);
    samples_.fetch_add(1, std::memory_order_relaxed);
  }
  type_.delete_data(sample);
}

std::string SimClock::summary() const {
  uint64_t n = samples_.load();
  if (n == 0)
    return std::string("clock: no sample on ") + kTopic +
           " (--use-sim-time): age() measured stamps against time 0 all along";
  return "clock: " + std::to_string(n) + " samples on " + kTopic + ", the last at " +
         decimal_seconds(now()) + "s";
}

}  // namespace arbc::dds
