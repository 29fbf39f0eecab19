// What the Twist interop programs share: a participant with ROS 2's Twist registered and a
// topic of it; their QoS, reliable keep-last (ROS 2's default profile, with a deeper history),
// is interop_participant.h's. Plain Fast-DDS and the types fastddsgen generated from Twist.idl;
// no arbc code.
#pragma once

#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include "TwistPubSubTypes.h"
#include "interop_participant.h"

namespace interop {

namespace fdds = eprosima::fastdds::dds;

// The participant of domain `domain` with the Twist type registered; exits on failure.
inline fdds::DomainParticipant* participant(int domain, const char* name) {
  fdds::DomainParticipant* p = plain_participant(domain, name);
  fdds::TypeSupport type(new geometry_msgs::msg::dds_::Twist_PubSubType());
  type.register_type(p);
  return p;
}

inline fdds::Topic* topic(fdds::DomainParticipant* p, const std::string& name) {
  return p->create_topic(name, "geometry_msgs::msg::dds_::Twist_", fdds::TOPIC_QOS_DEFAULT);
}

}  // namespace interop
