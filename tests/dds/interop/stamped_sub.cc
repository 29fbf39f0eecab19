// A plain Fast-DDS program (no arbc in it) that subscribes to ROS 2 TwistStampeds on
// rt/out/stamped and arbc_test Widths on rt/out/widths (Stamped.idl) and prints each sample it
// receives as one line of stamped_format.h's text, the text stamped_pub prints for what it
// sent. It stops `linger` seconds after the last sample (or after `timeout` seconds with none).
// usage: stamped_sub DOMAIN LINGER TIMEOUT
#include <chrono>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <thread>

#include "StampedPubSubTypes.h"
#include "interop_participant.h"
#include "stamped_format.h"

namespace {

namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;

fdds::DataReader* reader(fdds::DomainParticipant* p, fdds::Subscriber* sub, const char* topic,
                         const char* type) {
  fdds::DataReaderQos qos = sub->get_default_datareader_qos();
  interop::reliable(qos);
  return sub->create_datareader(p->create_topic(topic, type, fdds::TOPIC_QOS_DEFAULT), qos);
}

// Takes r's next sample and prints its line; false when there is none.
template <class T>
bool take(fdds::DataReader* r) {
  T sample;
  fdds::SampleInfo info;
  if (r->take_next_sample(&sample, &info) != ReturnCode_t::RETCODE_OK) return false;
  if (info.valid_data) {
    std::printf("%s\n", stamped::line(sample).c_str());
    std::fflush(stdout);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: stamped_sub DOMAIN LINGER TIMEOUT\n");
    return 2;
  }
  double linger = std::atof(argv[2]), timeout = std::atof(argv[3]);
  fdds::DomainParticipant* p = interop::plain_participant(std::atoi(argv[1]), "stamped_sub");
  fdds::TypeSupport(new geometry_msgs::msg::dds_::TwistStamped_PubSubType()).register_type(p);
  fdds::TypeSupport(new arbc_test::msg::dds_::Widths_PubSubType()).register_type(p);
  fdds::Subscriber* sub = p->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  fdds::DataReader* st =
      reader(p, sub, "rt/out/stamped", "geometry_msgs::msg::dds_::TwistStamped_");
  fdds::DataReader* wi = reader(p, sub, "rt/out/widths", "arbc_test::msg::dds_::Widths_");
  std::fprintf(stderr, "stamped_sub: listening\n");
  interop::take_until_quiet(
      [&] {
        return take<geometry_msgs::msg::dds_::TwistStamped_>(st) ||
               take<arbc_test::msg::dds_::Widths_>(wi);
      },
      linger, timeout);
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}
