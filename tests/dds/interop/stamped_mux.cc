// A joystick and a navigation stack as one plain Fast-DDS program (no arbc in it) that stamps
// its ROS 2 TwistStampeds with the wall clock, as ROS 2 nodes do, some of them stale. Every
// 50 ms tick (TICKS of them) navigation writes a command on rt/in/nav; at ticks 20 to 29 and 45
// the joystick writes one on rt/in/joy, after navigation's. The stale ones are stamped STALE_MS
// milliseconds ago: navigation's at ticks 5, 12, 55 and 62, the joystick's at 24 and 45 (so the
// last joystick command, at 45, is stale: it must not hold navigation off). A command's
// linear.x is 1000 for navigation, 2000 for the joystick, plus the tick. For each sample it
// prints `sent SOURCE TICK fresh|stale MS` (MS: milliseconds since the first write, on the
// steady clock) and then the sample as one line of stamped_format.h's text, for
// tests/dds/stamped_mux.py.
// usage: stamped_mux DOMAIN TICKS STALE_MS
#include <chrono>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <set>
#include <thread>

#include "StampedPubSubTypes.h"
#include "interop_participant.h"
#include "stamped_clock.h"
#include "stamped_format.h"

namespace {

using namespace std::chrono_literals;
namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;
using geometry_msgs::msg::dds_::TwistStamped_;

const std::set<int> kNavStale = {5, 12, 55, 62};
const std::set<int> kJoyStale = {24, 45};

bool joystick_speaks(int tick) { return (tick >= 20 && tick <= 29) || tick == 45; }

fdds::DataWriter* writer(fdds::DomainParticipant* p, fdds::Publisher* pub, const char* topic) {
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  return pub->create_datawriter(
      p->create_topic(topic, "geometry_msgs::msg::dds_::TwistStamped_", fdds::TOPIC_QOS_DEFAULT),
      qos);
}

struct Source {
  const char* name;
  fdds::DataWriter* w;
  int base;
  const std::set<int>* stale;
};

// Writes the source's command of `tick` and prints it; false if Fast-DDS refused it.
bool write(const Source& s, int tick, std::chrono::milliseconds stale_ms,
           std::chrono::steady_clock::time_point start) {
  bool is_stale = s.stale->count(tick) > 0;
  TwistStamped_ m = stamped::stamped_now(is_stale ? stale_ms : 0ms, s.base + tick);
  auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() -
                                                                  start);
  if (!s.w->write(&m)) return false;
  std::printf("sent %s %d %s %lld\n%s\n", s.name, tick, is_stale ? "stale" : "fresh",
              static_cast<long long>(ms.count()), stamped::line(m).c_str());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: stamped_mux DOMAIN TICKS STALE_MS\n");
    return 2;
  }
  int ticks = std::atoi(argv[2]);
  std::chrono::milliseconds stale(std::atoi(argv[3]));
  fdds::DomainParticipant* p = interop::plain_participant(std::atoi(argv[1]), "stamped_mux");
  fdds::TypeSupport(new geometry_msgs::msg::dds_::TwistStamped_PubSubType()).register_type(p);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  Source nav{"nav", writer(p, pub, "rt/in/nav"), 1000, &kNavStale};
  Source joy{"joy", writer(p, pub, "rt/in/joy"), 2000, &kJoyStale};
  if (!interop::matched(nav.w) || !interop::matched(joy.w)) {
    std::fprintf(stderr, "stamped_mux: no reader on rt/in/nav or rt/in/joy in 30 s\n");
    return 3;
  }
  std::this_thread::sleep_for(1s);  // the mediator matches the subscriber too
  auto start = std::chrono::steady_clock::now();
  for (int tick = 0; tick < ticks; ++tick) {
    std::this_thread::sleep_until(start + tick * 50ms);
    if (!write(nav, tick, stale, start) ||
        (joystick_speaks(tick) && !write(joy, tick, stale, start))) {
      std::fprintf(stderr, "stamped_mux: Fast-DDS refused a sample\n");
      return 3;
    }
    std::fflush(stdout);
  }
  bool acked = nav.w->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(10, 0)) ==
                   ReturnCode_t::RETCODE_OK &&
               joy.w->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(10, 0)) ==
                   ReturnCode_t::RETCODE_OK;
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return acked ? 0 : 3;
}
