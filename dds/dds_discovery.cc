// What remote endpoints announce at discovery: a publisher or subscriber on one of this
// process's topics with another type never matches (DDS matches by type name), so its
// messages would silently not arrive. Report it, naming the topic and both types.
#include <chrono>
#include <thread>

#include "dds/dds_transport_internal.h"

namespace arbc::dds {

namespace {

std::string text_of(const eprosima::fastdds::dds::UserDataQosPolicy& data) {
  const auto& bytes = data.data_vec();
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

void DiscoveryListener::on_publisher_discovery(
    fdds::DomainParticipant*, eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) {
  if (info.status != eprosima::fastrtps::rtps::WriterDiscoveryInfo::DISCOVERED_WRITER) return;
  transport_->check_remote(info.info.topicName().to_string(), info.info.typeName().to_string(),
                           text_of(info.info.m_qos.m_userData), "publisher");
}

void DiscoveryListener::on_subscriber_discovery(
    fdds::DomainParticipant*, eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) {
  if (info.status != eprosima::fastrtps::rtps::ReaderDiscoveryInfo::DISCOVERED_READER) return;
  transport_->check_remote(info.info.topicName().to_string(), info.info.typeName().to_string(),
                           text_of(info.info.m_qos.m_userData), "subscriber");
}

// DDS threads. type_of_topic_ is complete before the participant discovers anything (open()
// creates every endpoint before returning, and is not called again), so it is read unlocked.
void DdsTransport::check_remote(const std::string& topic, const std::string& type,
                                const std::string& user_data, const char* what) {
  if (closing_) return;
  auto it = type_of_topic_.find(topic);
  if (it == type_of_topic_.end()) return;
  const std::string& ours = it->second;
  std::string line;
  if (type != ours) {
    line = "DDS: type mismatch on topic " + topic + ": a remote " + what + " uses type " + type +
           ", this process uses " + ours + "; they do not match, so nothing flows between them";
  } else if (user_data.rfind("arbc-type=", 0) == 0) {
    std::string remote = user_data.substr(10);
    std::string local = port_of_topic_.count(topic)
                            ? app_.find_port(port_of_topic_.at(topic))->type->to_string()
                            : remote;
    if (remote != local)
      line = "DDS: type mismatch on topic " + topic + ": both sides call the type " + ours +
             " but a remote " + what + " means " + remote + " and this process " + local +
             "; samples will not decode (counted as bad-type)";
  }
  if (line.empty()) return;
  {
    std::lock_guard<std::mutex> lock(mismatch_mutex_);
    if (!mismatches_.insert(line).second) return;
  }
  report(line);
}

// A topic expects a peer when the app connects its port: an output read by some connection,
// an input some connection delivers to. Others (an output nothing reads) may stay alone.
std::vector<std::string> DdsTransport::topics_without_peers() const {
  auto connected = [&](const std::string& port, bool as_source) {
    for (const model::Connection& c : app_.connections) {
      if ((as_source ? c.source : c.destination) == port) return true;
    }
    return false;
  };
  std::vector<std::string> alone;
  for (const auto& r : readers_) {
    if (r->publishers == 0 && connected(r->port.qualified, !r->input)) alone.push_back(r->topic);
  }
  for (const auto& w : writers_) {
    if (w->subscribers == 0 && connected(w->port.qualified, !w->input)) alone.push_back(w->topic);
  }
  return alone;
}

// Waits (wall clock) until every topic that expects a peer has one, so that the first
// messages of a run are not published before anyone listens; then a short grace, because a
// match seen here may not be seen yet by the other side. Gives up after wait_peers seconds.
void DdsTransport::start(const std::atomic<bool>* interrupt) {
  if (options_.wait_peers <= 0 || !participant_) return;
  using Clock = std::chrono::steady_clock;
  auto begin = Clock::now();
  auto deadline = begin + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(options_.wait_peers));
  std::vector<std::string> alone = topics_without_peers();
  while (!alone.empty() && Clock::now() < deadline && !(interrupt && interrupt->load())) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    alone = topics_without_peers();
  }
  double waited = std::chrono::duration<double>(Clock::now() - begin).count();
  char line[160];
  if (alone.empty()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    std::snprintf(line, sizeof line, "DDS: every connected topic has a peer (after %.1f s)",
                  waited);
    sink_->report(line);
    return;
  }
  std::string names;
  for (const std::string& t : alone) names += (names.empty() ? "" : ", ") + t;
  std::snprintf(line, sizeof line, "DDS: starting after %.1f s with no peer yet on ", waited);
  sink_->report(line + names + " (what is published there is lost until a peer comes)");
}

}  // namespace arbc::dds
