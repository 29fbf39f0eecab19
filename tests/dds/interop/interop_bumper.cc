// A bumper as a plain Fast-DDS program (no arbc in it): publishes std_msgs/msg/Bool on
// rt/bumper every 50 ms, as a ROS 2 node would on /bumper with the sensor-data profile (best
// effort): released for 2 s, pressed for 1 s, released for 2 s; then exits. With `held S`: pressed
// the whole time, for S seconds (a mediator restarted while the bumper is held, bumper_restart.py).
// usage: interop_bumper DOMAIN [held SECONDS]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <string>
#include <thread>

#include "BoolPubSubTypes.h"

namespace fdds = eprosima::fastdds::dds;

int main(int argc, char** argv) {
  bool held = argc == 4 && std::string(argv[2]) == "held";
  if (argc != 2 && !held) {
    std::fprintf(stderr, "usage: interop_bumper DOMAIN [held SECONDS]\n");
    return 2;
  }
  int samples = held ? static_cast<int>(std::atof(argv[3]) * 20) : 100;  // one per 50 ms
  fdds::DomainParticipantFactory* factory = fdds::DomainParticipantFactory::get_instance();
  factory->load_profiles();  // FASTRTPS_DEFAULT_PROFILES_FILE (interop_common.h says why)
  fdds::DomainParticipantQos pqos = factory->get_default_participant_qos();
  pqos.name("interop_bumper");
  fdds::DomainParticipant* p = factory->create_participant(std::atoi(argv[1]), pqos);
  if (!p) return 3;
  fdds::TypeSupport type(new std_msgs::msg::dds_::Bool_PubSubType());
  type.register_type(p);
  fdds::Topic* topic =
      p->create_topic("rt/bumper", "std_msgs::msg::dds_::Bool_", fdds::TOPIC_QOS_DEFAULT);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 5;
  fdds::DataWriter* writer = pub->create_datawriter(topic, qos);
  int pressed = 0;
  for (int i = 0; i < samples; ++i) {
    std_msgs::msg::dds_::Bool_ b;
    b.data(held || (i >= 40 && i < 60));
    pressed += b.data();
    writer->write(&b);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::printf("interop_bumper: sent %d, %d pressed\n", samples, pressed);
  p->delete_contained_entities();
  factory->delete_participant(p);
  return 0;
}
