// A plain Fast-DDS program (no arbc in it), as rqt_robot_monitor or a latched-topic echo would
// be: subscribes to an arbc mediator's status topic STATUS_TOPIC (reliable, transient local: a
// late subscriber reads the last status) and, with `diagnostics`, to rt/diagnostics, and prints
// each sample as one line with the wall seconds since it started:
//   T status LEVEL|NAME|MESSAGE|key=value;key=value;...
//   T diagnostics SEC.NANOSEC|NAME LEVEL MESSAGE {key=value;...}|...
// It stops `linger` seconds after the last sample (or after `timeout` seconds with none).
// usage: diag_sub DOMAIN STATUS_TOPIC LINGER TIMEOUT [diagnostics]
#include <chrono>
#include <cstring>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <string>

#include "DiagnosticPubSubTypes.h"
#include "interop_participant.h"

namespace {

namespace fdds = eprosima::fastdds::dds;
namespace dm = diagnostic_msgs::msg::dds_;
using eprosima::fastrtps::types::ReturnCode_t;
using Clock = std::chrono::steady_clock;

const Clock::time_point kStart = Clock::now();

double since_start() { return std::chrono::duration<double>(Clock::now() - kStart).count(); }

std::string values(const dm::DiagnosticStatus_& s) {
  std::string out;
  for (const dm::KeyValue_& kv : s.values()) out += kv.key() + "=" + kv.value() + ";";
  return out;
}

bool take_status(fdds::DataReader* r) {
  dm::DiagnosticStatus_ s;
  fdds::SampleInfo info;
  if (r->take_next_sample(&s, &info) != ReturnCode_t::RETCODE_OK) return false;
  if (info.valid_data)
    std::printf("%.3f status %d|%s|%s|%s\n", since_start(), static_cast<int>(s.level()),
                s.name().c_str(), s.message().c_str(), values(s).c_str());
  std::fflush(stdout);
  return true;
}

bool take_array(fdds::DataReader* r) {
  if (!r) return false;
  dm::DiagnosticArray_ a;
  fdds::SampleInfo info;
  if (r->take_next_sample(&a, &info) != ReturnCode_t::RETCODE_OK) return false;
  if (!info.valid_data) return true;
  std::printf("%.3f diagnostics %d.%09u", since_start(), a.header().stamp().sec(),
              a.header().stamp().nanosec());
  for (const dm::DiagnosticStatus_& s : a.status())
    std::printf("|%s %d %s {%s}", s.name().c_str(), static_cast<int>(s.level()),
                s.message().c_str(), values(s).c_str());
  std::printf("\n");
  std::fflush(stdout);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) {
    std::fprintf(stderr, "usage: diag_sub DOMAIN STATUS_TOPIC LINGER TIMEOUT [diagnostics]\n");
    return 2;
  }
  double linger = std::atof(argv[3]), timeout = std::atof(argv[4]);
  bool diagnostics = argc == 6 && std::strcmp(argv[5], "diagnostics") == 0;
  fdds::DomainParticipant* p = interop::plain_participant(std::atoi(argv[1]), "diag_sub");
  fdds::TypeSupport(new dm::DiagnosticStatus_PubSubType()).register_type(p);
  fdds::TypeSupport(new dm::DiagnosticArray_PubSubType()).register_type(p);
  fdds::Subscriber* sub = p->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  fdds::DataReaderQos qos = sub->get_default_datareader_qos();
  interop::reliable(qos);
  qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
  fdds::DataReader* status = sub->create_datareader(
      p->create_topic(argv[2], "diagnostic_msgs::msg::dds_::DiagnosticStatus_",
                      fdds::TOPIC_QOS_DEFAULT),
      qos);
  fdds::DataReader* array = nullptr;
  if (diagnostics) {
    interop::reliable(qos);
    array = sub->create_datareader(
        p->create_topic("rt/diagnostics", "diagnostic_msgs::msg::dds_::DiagnosticArray_",
                        fdds::TOPIC_QOS_DEFAULT),
        qos);
  }
  std::fprintf(stderr, "diag_sub: listening\n");
  interop::take_until_quiet([&] { return take_status(status) || take_array(array); }, linger,
                            timeout);
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}
