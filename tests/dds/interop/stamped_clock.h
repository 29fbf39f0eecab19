// A TwistStamped stamped as a ROS 2 node stamps it: the wall clock's seconds and nanoseconds
// since the epoch, `ago` before now (the stale commands of stamped_ages.cc and stamped_mux.cc).
#pragma once

#include <chrono>

#include "Stamped.h"

namespace stamped {

inline geometry_msgs::msg::dds_::TwistStamped_ stamped_now(std::chrono::milliseconds ago,
                                                           double x) {
  auto since_epoch = std::chrono::system_clock::now().time_since_epoch() - ago;
  auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(since_epoch).count();
  geometry_msgs::msg::dds_::TwistStamped_ m;
  m.header().stamp().sec(static_cast<int32_t>(ns / 1000000000));
  m.header().stamp().nanosec(static_cast<uint32_t>(ns % 1000000000));
  m.header().frame_id("base_link");
  m.twist().linear().x(x);
  return m;
}

}  // namespace stamped
