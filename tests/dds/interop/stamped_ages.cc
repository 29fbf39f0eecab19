// A navigation stack as a plain Fast-DDS program (no arbc in it) that stamps its ROS 2
// TwistStampeds with the wall clock, as a ROS 2 node does, some of them stale: it writes COUNT
// samples on rt/in/stamped, 50 ms apart, sample i (from 1) with linear.x = i, stamped now for
// odd i and STALE_MS milliseconds ago for even i. It prints each sample it wrote as one line of
// stamped_format.h's text, then `fresh i` or `stale i`, for tests/dds/ages.py.
// With SIM_SECONDS it plays a simulator too, as ROS 2 nodes with use_sim_time see one: it
// publishes rosgraph_msgs/msg/Clock on rt/clock, from SIM_SECONDS on and 50 ms further with each
// sample, and stamps the samples with that time instead of the wall clock's.
// usage: stamped_ages DOMAIN COUNT STALE_MS [SIM_SECONDS]
#include <chrono>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
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

// A sample stamped `ago` before the simulated time `sim`.
TwistStamped_ stamped_at(std::chrono::nanoseconds sim, std::chrono::milliseconds ago, double x) {
  int64_t ns = (sim - ago).count();
  TwistStamped_ m;
  m.header().stamp().sec(static_cast<int32_t>(ns / 1000000000));
  m.header().stamp().nanosec(static_cast<uint32_t>(ns % 1000000000));
  m.header().frame_id("base_link");
  m.twist().linear().x(x);
  return m;
}

// The simulator's /clock, or none without SIM_SECONDS.
struct SimClock {
  fdds::DataWriter* w = nullptr;
  std::chrono::nanoseconds now{0};
  bool tick(std::chrono::nanoseconds t) {
    now = t;
    rosgraph_msgs::msg::dds_::Clock_ c;
    c.clock().sec(static_cast<int32_t>(t.count() / 1000000000));
    c.clock().nanosec(static_cast<uint32_t>(t.count() % 1000000000));
    return !w || w->write(&c);
  }
};

SimClock sim_clock(fdds::DomainParticipant* p, fdds::Publisher* pub, const char* seconds) {
  SimClock clock;
  if (!seconds) return clock;
  fdds::TypeSupport(new rosgraph_msgs::msg::dds_::Clock_PubSubType()).register_type(p);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  clock.w = pub->create_datawriter(
      p->create_topic("rt/clock", "rosgraph_msgs::msg::dds_::Clock_", fdds::TOPIC_QOS_DEFAULT),
      qos);
  clock.now = std::chrono::nanoseconds(std::atoll(seconds) * 1000000000LL);
  return clock;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: stamped_ages DOMAIN COUNT STALE_MS [SIM_SECONDS]\n");
    return 2;
  }
  int count = std::atoi(argv[2]);
  std::chrono::milliseconds stale(std::atoi(argv[3]));
  fdds::DomainParticipant* p = interop::plain_participant(std::atoi(argv[1]), "stamped_ages");
  fdds::TypeSupport(new geometry_msgs::msg::dds_::TwistStamped_PubSubType()).register_type(p);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  fdds::DataWriter* w = pub->create_datawriter(
      p->create_topic("rt/in/stamped", "geometry_msgs::msg::dds_::TwistStamped_",
                      fdds::TOPIC_QOS_DEFAULT),
      qos);
  SimClock clock = sim_clock(p, pub, argc == 5 ? argv[4] : nullptr);
  if (!interop::matched(w) || (clock.w && !interop::matched(clock.w))) {
    std::fprintf(stderr, "stamped_ages: no reader on rt/in/stamped (or rt/clock) in 30 s\n");
    return 3;
  }
  clock.tick(clock.now);
  std::this_thread::sleep_for(1s);  // the mediator matches the subscriber too
  for (int i = 1; i <= count; ++i) {
    bool fresh = i % 2 == 1;
    TwistStamped_ m = clock.w ? stamped_at(clock.now, fresh ? 0ms : stale, i)
                              : stamped::stamped_now(fresh ? 0ms : stale, i);
    if (!w->write(&m)) {
      std::fprintf(stderr, "stamped_ages: Fast-DDS refused a sample\n");
      return 3;
    }
    std::printf("%s\n%s %d\n", stamped::line(m).c_str(), fresh ? "fresh" : "stale", i);
    std::fflush(stdout);
    std::this_thread::sleep_for(50ms);
    clock.tick(clock.now + 50ms);
  }
  bool acked = w->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(10, 0)) ==
               ReturnCode_t::RETCODE_OK;
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return acked ? 0 : 3;
}
