// A robot base as a plain Fast-DDS program (no arbc in it): reads Twist on rt/cmd_vel, as a
// ROS 2 node would on /cmd_vel, and prints each message's linear.x, one per line. It stops
// `linger` seconds after the last message (or after `timeout` seconds with none).
// QOS words (interop_common.h) change its reader's QoS: `best_effort`, `transient_local`.
// usage: interop_sub DOMAIN LINGER TIMEOUT [QOS...]
#include <chrono>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <thread>

#include "interop_common.h"

namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: interop_sub DOMAIN LINGER TIMEOUT [QOS...]\n");
    return 2;
  }
  double linger = std::atof(argv[2]), timeout = std::atof(argv[3]);
  fdds::DomainParticipant* p = interop::participant(std::atoi(argv[1]), "interop_sub");
  fdds::Subscriber* sub = p->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  fdds::DataReaderQos qos = sub->get_default_datareader_qos();
  interop::qos_from_args(qos, argc, argv, 4);
  fdds::DataReader* reader = sub->create_datareader(interop::topic(p, "rt/cmd_vel"), qos);
  std::printf("interop_sub: listening\n");
  std::fflush(stdout);
  interop::take_until_quiet(
      [&] {
        geometry_msgs::msg::dds_::Twist_ t;
        fdds::SampleInfo info;
        while (reader->take_next_sample(&t, &info) == ReturnCode_t::RETCODE_OK) {
          if (!info.valid_data) continue;  // a writer gone: no sample, no activity
          std::printf("%g\n", t.linear().x());
          std::fflush(stdout);
          return true;
        }
        return false;
      },
      linger, timeout);
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}
