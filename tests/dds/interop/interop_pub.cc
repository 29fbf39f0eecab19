// A joystick and a planner as one plain Fast-DDS program (no arbc in it): publishes Twist on
// rt/joy/cmd_vel and rt/nav/cmd_vel, as ROS 2 nodes would on /joy/cmd_vel and /nav/cmd_vel.
// Each message's linear.x numbers it. The script (teleop.spec selects what the comments say):
//   1. nav 1..10, every 50 ms, and a joystick at rest (all zero) after nav 5: nav passes, the
//      resting joystick is not accepted;
//   2. joy 101..110 every 100 ms, each followed 60 ms later by nav 201..210: joy passes, nav is
//      held off by joy's 2 s hold;
//   3. 4 s later (the hold is over) nav 301..310 every 50 ms: nav passes again.
// usage: interop_pub DOMAIN
#include <chrono>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <thread>

#include "interop_common.h"

namespace {

using namespace std::chrono_literals;
namespace fdds = eprosima::fastdds::dds;

fdds::DataWriter* writer(fdds::DomainParticipant* p, fdds::Publisher* pub, const char* name) {
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  return pub->create_datawriter(interop::topic(p, name), qos);
}

void send(fdds::DataWriter* w, double x) {
  geometry_msgs::msg::dds_::Twist_ t;
  t.linear().x(x);
  t.angular().z(x == 0 ? 0.0 : 0.5);
  w->write(&t);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: interop_pub DOMAIN\n");
    return 2;
  }
  fdds::DomainParticipant* p = interop::participant(std::atoi(argv[1]), "interop_pub");
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriter* joy = writer(p, pub, "rt/joy/cmd_vel");
  fdds::DataWriter* nav = writer(p, pub, "rt/nav/cmd_vel");
  if (!interop::matched(joy) || !interop::matched(nav)) {
    std::fprintf(stderr, "interop_pub: no reader on rt/joy/cmd_vel or rt/nav/cmd_vel in 30 s\n");
    return 3;
  }
  std::this_thread::sleep_for(500ms);  // the reader side sees the match too
  for (int i = 1; i <= 10; ++i) {
    send(nav, i);
    if (i == 5) send(joy, 0);  // at rest: not accepted
    std::this_thread::sleep_for(50ms);
  }
  std::this_thread::sleep_for(300ms);
  for (int i = 1; i <= 10; ++i) {
    send(joy, 100 + i);
    std::this_thread::sleep_for(60ms);
    send(nav, 200 + i);
    std::this_thread::sleep_for(40ms);
  }
  std::this_thread::sleep_for(4s);
  for (int i = 1; i <= 10; ++i) {
    send(nav, 300 + i);
    std::this_thread::sleep_for(50ms);
  }
  joy->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(5, 0));
  nav->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(5, 0));
  std::printf("interop_pub: sent 31 messages\n");
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}
