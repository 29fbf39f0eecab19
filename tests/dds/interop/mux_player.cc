// twist_mux's inputs as plain Fast-DDS programs would publish them (no arbc in it): plays a
// script of timed messages, Twists on input topics and std_msgs/msg/Bool on lock topics, each at
// its time after every topic's reader has matched. A script line is
//   SECONDS TOPIC twist X     a Twist with linear.x = X (it numbers the message)
//   SECONDS TOPIC bool 0|1    a Bool
// with TOPIC as on the wire (rt/nav_vel). twist_mux_run.py compares what a mediator of the
// imported configuration lets through with what twist_mux does on the same script.
// usage: mux_player DOMAIN SCRIPT
#include <chrono>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>
#include <vector>

#include "BoolPubSubTypes.h"
#include "interop_common.h"

namespace {

namespace fdds = eprosima::fastdds::dds;

struct Line {
  double at = 0;
  std::string topic, kind;
  double value = 0;
};

std::vector<Line> read_script(const char* path) {
  std::vector<Line> lines;
  std::ifstream in(path);
  for (std::string text; std::getline(in, text);) {
    std::istringstream words(text);
    Line l;
    if (words >> l.at >> l.topic >> l.kind >> l.value) lines.push_back(l);
  }
  return lines;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mux_player DOMAIN SCRIPT\n");
    return 2;
  }
  std::vector<Line> script = read_script(argv[2]);
  fdds::DomainParticipant* p = interop::participant(std::atoi(argv[1]), "mux_player");
  fdds::TypeSupport(new std_msgs::msg::dds_::Bool_PubSubType()).register_type(p);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  std::map<std::string, fdds::DataWriter*> writers;
  for (const Line& l : script) {
    if (writers.count(l.topic)) continue;
    fdds::Topic* t = l.kind == "bool" ? p->create_topic(l.topic, "std_msgs::msg::dds_::Bool_",
                                                        fdds::TOPIC_QOS_DEFAULT)
                                      : interop::topic(p, l.topic);
    writers[l.topic] = pub->create_datawriter(t, qos);
  }
  for (auto& [topic, w] : writers) {
    if (!interop::matched(w)) {
      std::fprintf(stderr, "mux_player: no reader on %s\n", topic.c_str());
      return 3;
    }
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // every reader ready to take
  auto start = std::chrono::steady_clock::now();
  for (const Line& l : script) {
    std::this_thread::sleep_until(start + std::chrono::duration<double>(l.at));
    if (l.kind == "bool") {
      std_msgs::msg::dds_::Bool_ b;
      b.data(l.value != 0);
      writers[l.topic]->write(&b);
    } else {
      geometry_msgs::msg::dds_::Twist_ t;
      t.linear().x(l.value);
      writers[l.topic]->write(&t);
    }
  }
  std::this_thread::sleep_for(std::chrono::seconds(1));  // reliable delivery of the last ones
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}
