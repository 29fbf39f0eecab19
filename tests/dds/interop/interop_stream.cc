// A planner as a plain Fast-DDS program (no arbc in it) that never stops: publishes Twist on
// rt/nav/cmd_vel every PERIOD_MS, numbered 1, 2, 3, ... in linear.x, until it is killed. It
// feeds the mediator while restart_peer.py kills and restarts the subscriber behind it.
// QOS words (interop_common.h) change its writer's QoS: `best_effort`, `transient_local`.
// usage: interop_stream DOMAIN PERIOD_MS [QOS...]
#include <chrono>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <thread>

#include "interop_common.h"

namespace fdds = eprosima::fastdds::dds;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: interop_stream DOMAIN PERIOD_MS [QOS...]\n");
    return 2;
  }
  const auto period = std::chrono::milliseconds(std::atoi(argv[2]));
  fdds::DomainParticipant* p = interop::participant(std::atoi(argv[1]), "interop_stream");
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::qos_from_args(qos, argc, argv, 3);
  fdds::DataWriter* nav = pub->create_datawriter(interop::topic(p, "rt/nav/cmd_vel"), qos);
  for (long i = 1;; ++i) {
    geometry_msgs::msg::dds_::Twist_ t;
    t.linear().x(static_cast<double>(i));
    t.angular().z(0.5);
    nav->write(&t);
    std::this_thread::sleep_for(period);
  }
}
