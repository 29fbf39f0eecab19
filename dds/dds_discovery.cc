// What remote endpoints announce at discovery: a publisher or subscriber on one of this
// process's topics with another type never matches (DDS matches by type name), so its
// messages would silently not arrive. Report it, naming the topic and both types. Likewise a
// second publisher on a topic this process writes as a mediator, and topics that never find
// a peer: each would leave a run wrong or idle without a word.
#include <algorithm>
#include <chrono>
#include <sstream>
#include <thread>

#include "core/join.h"
#include "dds/dds_transport_internal.h"
#include "dds/no_peer_reports.h"
#include "dds/qos_mismatch.h"
#include "dds/type_name_hint.h"
#include "runtime/executor.h"

namespace arbc::dds {

namespace {

std::string text_of(const eprosima::fastdds::dds::UserDataQosPolicy& data) {
  const auto& bytes = data.data_vec();
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

void DiscoveryListener::on_publisher_discovery(
    fdds::DomainParticipant* participant, eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) {
  if (info.status != eprosima::fastrtps::rtps::WriterDiscoveryInfo::DISCOVERED_WRITER) return;
  std::string topic = info.info.topicName().to_string();
  std::string user_data = text_of(info.info.m_qos.m_userData);
  transport_->check_remote(topic, info.info.typeName().to_string(), user_data, "publisher");
  // This process's own writers are no second publisher.
  if (info.info.guid().guidPrefix != participant->guid().guidPrefix)
    transport_->check_other_writer(topic, user_data);
}

void DiscoveryListener::on_participant_discovery(
    fdds::DomainParticipant* participant,
    eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) {
  using Info = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
  const auto& data = info.info;
  if (data.m_guid.guidPrefix == participant->guid().guidPrefix) return;
  std::ostringstream id;
  id << data.m_guid.guidPrefix;
  if (info.status == Info::REMOVED_PARTICIPANT || info.status == Info::DROPPED_PARTICIPANT) {
    shm_ports_.left(id.str(), info.status == Info::REMOVED_PARTICIPANT);
    return;
  }
  if (info.status != Info::DISCOVERED_PARTICIPANT) return;
  std::vector<uint32_t> ports;
  for (const auto* list : {&data.metatraffic_locators.unicast, &data.default_locators.unicast}) {
    for (const auto& locator : *list) {
      if (locator.kind == LOCATOR_KIND_SHM) ports.push_back(locator.port);
    }
  }
  std::string name = data.m_participantName.to_string();
  auto before = shm_ports_.discovered(id.str(), name, ports);
  if (!before || transport_->closing()) return;
  transport_->report(
      "DDS: participant '" + name + "' started on the shared-memory port " +
      std::to_string(before->port) + " of '" + before->name +
      "', which vanished without leaving (killed?): Fast-DDS 2.9 may go on writing into the old "
      "segment, so it may hear this process seconds late or not at all; run that program over "
      "UDP only, or start this process again too "
      "(docs/distributed.md#killing-and-restarting-a-process)");
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
  if (closing_ || user_data == kStatusUserData) return;
  auto it = type_of_topic_.find(topic);
  if (it == type_of_topic_.end()) {
    std::lock_guard<std::mutex> lock(mismatch_mutex_);
    seen_remote_.emplace(topic, type);
    return;
  }
  const std::string& ours = it->second;
  std::string line;
  if (type != ours) {
    line = "DDS: type mismatch on topic " + topic + ": a remote " + what + " uses type " + type +
           ", this process uses " + ours + "; they do not match, so nothing flows between them";
    auto port = port_of_topic_.find(topic);
    const model::Port* p = port == port_of_topic_.end() ? nullptr : app_.find_port(port->second);
    if (p && p->type &&
        (p->type->kind == Type::Kind::Record || p->type->kind == Type::Kind::List)) {
      line += type_name_hint(options_.deployment, port->second, naming_->spec_name(*p->type), type);
    }
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

// The arbitration is proved for what this process delivers; anything else a module reads on
// its input topic bypasses it (a second mediator doubles every delivery). A writer may be
// discovered before this process creates its own on the topic: add_writer asks again.
void DdsTransport::check_other_writer(const std::string& topic, const std::string& user_data) {
  bool arbc = user_data.rfind("arbc-type=", 0) == 0;
  std::string port;
  {
    std::lock_guard<std::mutex> lock(mismatch_mutex_);
    remote_writers_[topic] |= arbc;
    auto it = mediated_input_of_topic_.find(topic);
    if (it == mediated_input_of_topic_.end()) return;
    port = it->second;
  }
  report_other_writer(topic, port, arbc);
}

void DdsTransport::report_other_writer(const std::string& topic, const std::string& port,
                                       bool arbc) {
  if (closing_) return;
  std::string module = port.substr(0, port.find('.'));
  std::string line =
      arbc ? "DDS: another arbc process also mediates " + port + " (it publishes on topic " +
                 topic + "): " + module + " receives what both select; give --mediate " + module +
                 " to one process only"
           : "DDS: another program publishes on topic " + topic +
                 ", which this process writes as the mediator of " + port + ": what it sends " +
                 "reaches " + module + " unarbitrated; give that program a topic of its own " +
                 "and connect it to " + port + " in the spec";
  {
    std::lock_guard<std::mutex> lock(mismatch_mutex_);
    if (!mismatches_.insert(line).second) return;
  }
  report(line);
}

namespace {

// DDS's name for a QoS policy, as its specification writes it.
std::string policy_name(fdds::QosPolicyId_t id) {
  switch (id) {
    case fdds::DEADLINE_QOS_POLICY_ID:
      return "DEADLINE";
    case fdds::LIVELINESS_QOS_POLICY_ID:
      return "LIVELINESS";
    case fdds::OWNERSHIP_QOS_POLICY_ID:
      return "OWNERSHIP";
    case fdds::DESTINATIONORDER_QOS_POLICY_ID:
      return "DESTINATION_ORDER";
    case fdds::PRESENTATION_QOS_POLICY_ID:
      return "PRESENTATION";
    case fdds::LATENCYBUDGET_QOS_POLICY_ID:
      return "LATENCY_BUDGET";
    case fdds::DATAREPRESENTATION_QOS_POLICY_ID:
      return "DATA_REPRESENTATION";
    default:
      return "QoS policy " + std::to_string(static_cast<int>(id));
  }
}

}  // namespace

void DdsTransport::report_qos_mismatch(const std::string& topic, const std::string& port,
                                       bool reader, fdds::QosPolicyId_t policy) {
  if (closing_) return;
  QosMismatch m{topic, port, reader, QosPolicy::Other, policy_name(policy)};
  if (policy == fdds::RELIABILITY_QOS_POLICY_ID) m.policy = QosPolicy::Reliability;
  if (policy == fdds::DURABILITY_QOS_POLICY_ID) m.policy = QosPolicy::Durability;
  std::string line = qos_mismatch_text(options_.deployment, m);
  {
    std::lock_guard<std::mutex> lock(mismatch_mutex_);
    qos_mismatched_.insert(topic);
    if (!mismatches_.insert(line).second) return;
  }
  report(line);
}

// A topic expects a peer when the app connects its port: an output read by some connection,
// an input some connection delivers to. Others (an output nothing reads) may stay alone.
bool DdsTransport::expects_peer(const TransportPort& port, bool input) const {
  for (const model::Connection& c : app_.connections) {
    if ((input ? c.destination : c.source) == port.qualified) return true;
  }
  return false;
}

std::vector<std::string> DdsTransport::topics_without_peers() const {
  std::vector<std::string> alone;
  for (const auto& r : readers_) {
    if (r->publishers == 0 && expects_peer(r->port, r->input)) alone.push_back(r->topic);
  }
  for (const auto& w : writers_) {
    if (w->subscribers == 0 && expects_peer(w->port, w->input)) alone.push_back(w->topic);
  }
  return alone;
}

namespace {

std::string last_name(const std::string& topic) { return topic.substr(topic.rfind('/') + 1); }

}  // namespace

// A peer that never comes is most often in another domain, or on a topic or type that differs
// from ours by a typo or by the ROS 2 naming ("rt/" and "dds_::T_"): name what to check, and
// the remote topics seen that look like ours.
std::string DdsTransport::peer_hint(const std::vector<std::string>& alone) const {
  std::vector<std::string> near, qos;
  {
    std::lock_guard<std::mutex> lock(mismatch_mutex_);
    for (const std::string& topic : alone) {
      if (qos_mismatched_.count(topic)) qos.push_back(topic);
    }
    for (const auto& seen : seen_remote_) {
      // Named, not bound: clang 14 cannot capture a structured binding in a lambda.
      const std::string &topic = seen.first, &type = seen.second;
      bool like = std::any_of(alone.begin(), alone.end(), [&](const std::string& ours) {
        return type_of_topic_.at(ours) == type || last_name(ours) == last_name(topic);
      });
      if (like && near.size() < 5) near.push_back(topic + " (" + type + ")");
    }
  }
  // A peer that DDS refused for its QoS is there: the question is not where it is.
  std::string refused =
      qos.empty() ? ""
                  : "; a program on " + join(qos) + " has a QoS that does not match (said above)";
  if (qos.size() == alone.size()) return refused;
  std::string hint = refused + "; is every program in domain " + std::to_string(options_.domain) +
                     " (--domain, ROS_DOMAIN_ID), with these topic and type names (--deploy)?";
  if (near.empty()) return hint;
  std::string names;
  for (const std::string& n : near) names += (names.empty() ? "" : ", ") + n;
  return hint + " Seen in this domain: " + names;
}

std::vector<std::string> DdsTransport::topics_never_matched() const {
  std::vector<std::string> alone;
  for (const std::string& topic : topics_without_peers()) {
    bool matched = false;
    for (const auto& r : readers_) matched |= r->topic == topic && r->ever_matched;
    for (const auto& w : writers_) matched |= w->topic == topic && w->ever_matched;
    if (!matched) alone.push_back(topic);
  }
  return alone;
}

void DdsTransport::report_unmatched(int k) {
  std::vector<std::string> alone = topics_never_matched();
  if (alone.empty()) return;
  std::string names;
  for (const std::string& t : alone) names += (names.empty() ? "" : ", ") + t;
  std::string after = wall_span_text(no_peer_report_at(k, options_.unmatched_after));
  sink_->report(std::string(k == 0 ? "DDS: no peer yet after " : "DDS: still no peer after ") +
                after + " on " + names + " (nothing flows there until one comes)" +
                peer_hint(alone));
  post_unmatched_report(k + 1);
}

double DdsTransport::wall_seconds_since_start() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at_).count();
}

void DdsTransport::post_unmatched_report(int k) {
  if (!(options_.unmatched_after > 0)) return;  // no reports
  Executor& ex = sink_->executor();
  double wait = no_peer_report_at(k, options_.unmatched_after) - wall_seconds_since_start();
  ex.post(later(ex.now(), nanos_from_seconds(std::max(0.0, wait) * options_.time_scale)),
          [this, k] {
            if (!closing_) report_unmatched(k);
          });
}

// Waits (wall clock) until every topic that expects a peer has one, so that the first
// messages of a run are not published before anyone listens; then a short grace, because a
// match seen here may not be seen yet by the other side. Gives up after wait_peers seconds.
void DdsTransport::start(const std::atomic<bool>* interrupt) {
  if (!participant_) return;
  started_at_ = std::chrono::steady_clock::now();
  if (options_.wait_peers <= 0) {
    post_unmatched_report(0);
    return;
  }
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
  sink_->report(line + names + " (what is published there is lost until a peer comes)" +
                peer_hint(alone));
  // Said again, as without the wait, at the reports' times still to come.
  int k = 1;
  while (options_.unmatched_after > 0 && no_peer_report_at(k, options_.unmatched_after) <= waited)
    ++k;
  post_unmatched_report(k);
}

}  // namespace arbc::dds
