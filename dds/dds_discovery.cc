// What remote endpoints announce at discovery: a publisher or subscriber on one of this
// process's topics with another type never matches (DDS matches by type name), so its
// messages would silently not arrive. Report it, naming the topic and both types.
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
    std::string local = port_of_topic_.count(topic) ? app_.find_port(port_of_topic_.at(topic))
                                                           ->type->to_string()
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

}  // namespace arbc::dds
