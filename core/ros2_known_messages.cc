#include "core/ros2_known_messages.h"

namespace arbc::ros2 {

const std::map<std::string, std::string>& known_message_texts() {
  static const std::map<std::string, std::string> texts = {
      {"builtin_interfaces/msg/Time", "int32 sec\nuint32 nanosec\n"},
      {"builtin_interfaces/msg/Duration", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/msg/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"std_msgs/msg/Bool", "bool data\n"},
      // What the DDS mediator's live status writes (dds/status_types.h).
      {"diagnostic_msgs/msg/KeyValue", "string key\nstring value\n"},
      {"diagnostic_msgs/msg/DiagnosticStatus",
       "byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\nbyte level\nstring name\n"
       "string message\nstring hardware_id\nKeyValue[] values\n"},
      {"diagnostic_msgs/msg/DiagnosticArray",
       "std_msgs/Header header\nDiagnosticStatus[] status\n"},
      {"std_msgs/msg/Int32", "int32 data\n"},
      {"std_msgs/msg/Int64", "int64 data\n"},
      {"std_msgs/msg/Float32", "float32 data\n"},
      {"std_msgs/msg/Float64", "float64 data\n"},
      {"std_msgs/msg/String", "string data\n"},
      {"geometry_msgs/msg/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/msg/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/msg/Point32", "float32 x\nfloat32 y\nfloat32 z\n"},
      {"geometry_msgs/msg/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
      {"geometry_msgs/msg/Pose2D", "float64 x\nfloat64 y\nfloat64 theta\n"},
      {"geometry_msgs/msg/Twist", "Vector3 linear\nVector3 angular\n"},
      {"geometry_msgs/msg/Accel", "Vector3 linear\nVector3 angular\n"},
      {"geometry_msgs/msg/Wrench", "Vector3 force\nVector3 torque\n"},
      {"geometry_msgs/msg/Pose", "Point position\nQuaternion orientation\n"},
      {"geometry_msgs/msg/TwistStamped", "std_msgs/Header header\nTwist twist\n"},
      {"geometry_msgs/msg/Vector3Stamped", "std_msgs/Header header\nVector3 vector\n"},
      {"geometry_msgs/msg/PoseStamped", "std_msgs/Header header\nPose pose\n"},
      {"geometry_msgs/msg/PointStamped", "std_msgs/Header header\nPoint point\n"},
  };
  return texts;
}

}  // namespace arbc::ros2
