// A planner as a plain Fast-DDS program (no arbc in it) whose Twist has the name ROS 2 gives it
// on the wire and a byte sequence after its vectors (TwistPadded.idl): each sample is longer
// than the spec's Twist by its own number of bytes. Once a reader listens on rt/nav/cmd_vel it
// writes COUNT samples at once, the k-th (from 0) padded with PADS[k % len(PADS)] bytes, then
// waits 2 s for them to be read (its history keeps them all) and exits.
// usage: interop_padded DOMAIN COUNT PAD...
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <thread>
#include <vector>

#include "TwistPaddedPubSubTypes.h"
#include "interop_participant.h"

namespace fdds = eprosima::fastdds::dds;
using namespace std::chrono_literals;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: interop_padded DOMAIN COUNT PAD...\n");
    return 2;
  }
  int count = std::atoi(argv[2]);
  std::vector<size_t> pads;
  for (int i = 3; i < argc; ++i) pads.push_back(static_cast<size_t>(std::atoi(argv[i])));
  fdds::DomainParticipantFactory* factory = fdds::DomainParticipantFactory::get_instance();
  factory->load_profiles();  // the test's profile (interop_common.h says why)
  fdds::DomainParticipantQos pqos = factory->get_default_participant_qos();
  pqos.name("interop_padded");
  fdds::DomainParticipant* p = factory->create_participant(std::atoi(argv[1]), pqos);
  if (!p) return 3;
  fdds::TypeSupport type(new geometry_msgs::msg::dds_::Twist_PubSubType());
  type.register_type(p);
  fdds::Topic* topic = p->create_topic("rt/nav/cmd_vel", "geometry_msgs::msg::dds_::Twist_",
                                       fdds::TOPIC_QOS_DEFAULT);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_ALL_HISTORY_QOS;
  qos.resource_limits().max_samples = count + 1;
  qos.resource_limits().max_samples_per_instance = count + 1;
  fdds::DataWriter* w = pub->create_datawriter(topic, qos);
  if (!w) return 3;
  if (!interop::matched(w)) return 4;  // 30 s without a reader
  for (int k = 0; k < count; ++k) {
    geometry_msgs::msg::dds_::Twist_ t;
    t.linear().x(static_cast<double>(k + 1));
    t.pad(std::vector<uint8_t>(pads[static_cast<size_t>(k) % pads.size()], 7));
    w->write(&t);
  }
  std::this_thread::sleep_for(2s);
  std::printf("interop_padded: wrote %d\n", count);
  return 0;
}
