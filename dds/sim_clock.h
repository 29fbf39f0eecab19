// ROS 2 simulated time (docs/distributed.md#simulated-time-clock): with --use-sim-time a DDS run
// reads the /clock topic (rosgraph_msgs/msg/Clock, on the wire rt/clock) as a ROS 2 node with
// use_sim_time does, and age() measures stamps against its last sample (0 before the first, as
// such a node's clock reads). The reader is best effort, keep last, so it matches a simulator's
// reliable or best-effort writer alike (rclcpp's ClockQoS).
#pragma once

#include <atomic>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <string>

#include "core/instant.h"

namespace arbc::dds {

class SimClock : public eprosima::fastdds::dds::DataReaderListener {
 public:
  // Registers the Clock type and reads rt/clock from now on. False with *error when the app's
  // own ports use that type, or Fast-DDS refuses.
  bool open(eprosima::fastdds::dds::DomainParticipant* participant,
            eprosima::fastdds::dds::Subscriber* subscriber, std::string* error);
  // Stops reading (the participant deletes the reader with its other entities).
  void close();
  // The last /clock sample's time since its epoch; 0 before the first.
  Nanos now() const { return Nanos(ns_.load(std::memory_order_acquire)); }
  // "clock: 312 samples on rt/clock, the last at 104.250s" (or that none came) for the run's end.
  std::string summary() const;

 private:
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override;

  eprosima::fastdds::dds::TypeSupport type_;
  eprosima::fastdds::dds::DataReader* reader_ = nullptr;
  std::atomic<int64_t> ns_{0};
  std::atomic<uint64_t> samples_{0};
};

}  // namespace arbc::dds
