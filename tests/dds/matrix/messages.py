"""The ROS 2 messages of the interop matrix (issue 41, "Done means"), as their .msg files
define them (ROS 2 Humble's common_interfaces and rcl_interfaces): the test writes these files
itself, since the repository ships no copy of ROS 2's. Field lists and widths are facts of the
wire format; comments are left out.

MATRIX lists the messages the test sends (the issue's 20, and arbc_test/Sized); DEFINITIONS
also holds the messages they use.
"""

DEFINITIONS = {
    "builtin_interfaces/Time": "int32 sec\nuint32 nanosec\n",
    "std_msgs/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "std_msgs/Bool": "bool data\n",
    "std_msgs/Int32": "int32 data\n",
    "std_msgs/Float32": "float32 data\n",
    "std_msgs/String": "string data\n",
    "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
    "geometry_msgs/Pose": "Point position\nQuaternion orientation\n",
    "geometry_msgs/Twist": "Vector3 linear\nVector3 angular\n",
    "geometry_msgs/TwistStamped": "std_msgs/Header header\nTwist twist\n",
    "geometry_msgs/Vector3Stamped": "std_msgs/Header header\nVector3 vector\n",
    "geometry_msgs/PoseStamped": "std_msgs/Header header\nPose pose\n",
    "geometry_msgs/PoseWithCovariance": "Pose pose\nfloat64[36] covariance\n",
    "geometry_msgs/TwistWithCovariance": "Twist twist\nfloat64[36] covariance\n",
    "sensor_msgs/LaserScan": (
        "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
        "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
        "float32[] ranges\nfloat32[] intensities\n"),
    "sensor_msgs/Range": (
        "uint8 ULTRASOUND=0\nuint8 INFRARED=1\nstd_msgs/Header header\nuint8 radiation_type\n"
        "float32 field_of_view\nfloat32 min_range\nfloat32 max_range\nfloat32 range\n"),
    "sensor_msgs/Imu": (
        "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\n"
        "float64[9] orientation_covariance\ngeometry_msgs/Vector3 angular_velocity\n"
        "float64[9] angular_velocity_covariance\ngeometry_msgs/Vector3 linear_acceleration\n"
        "float64[9] linear_acceleration_covariance\n"),
    "sensor_msgs/JointState": (
        "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
        "float64[] effort\n"),
    "sensor_msgs/Joy": "std_msgs/Header header\nfloat32[] axes\nint32[] buttons\n",
    "sensor_msgs/BatteryState": (
        "uint8 POWER_SUPPLY_STATUS_UNKNOWN=0\nuint8 POWER_SUPPLY_STATUS_CHARGING=1\n"
        "uint8 POWER_SUPPLY_HEALTH_GOOD=1\nuint8 POWER_SUPPLY_TECHNOLOGY_LION=2\n"
        "std_msgs/Header header\nfloat32 voltage\nfloat32 temperature\nfloat32 current\n"
        "float32 charge\nfloat32 capacity\nfloat32 design_capacity\nfloat32 percentage\n"
        "uint8 power_supply_status\nuint8 power_supply_health\nuint8 power_supply_technology\n"
        "bool present\nfloat32[] cell_voltage\nfloat32[] cell_temperature\nstring location\n"
        "string serial_number\n"),
    "nav_msgs/Odometry": (
        "std_msgs/Header header\nstring child_frame_id\n"
        "geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n"),
    "diagnostic_msgs/KeyValue": "string key\nstring value\n",
    "diagnostic_msgs/DiagnosticStatus": (
        "byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\nbyte level\nstring name\n"
        "string message\nstring hardware_id\nKeyValue[] values\n"),
    "diagnostic_msgs/DiagnosticArray": "std_msgs/Header header\nDiagnosticStatus[] status\n",
    # None of the 20 has a bounded sequence or string, nor a fixed array of messages. (No fixed
    # array of strings: the deserializer fastddsgen 2.x writes for `string pair[2]` skips the
    # member, so the plain program itself would drop it; dds/wire_types_test.cc passes a
    # `string<4>[2]` through Fast-DDS's own encoding.)
    "arbc_test/Sized": (
        "int16[<=4] few\nstring<=12 name\nstring<=3[<=2] tags\n"
        "geometry_msgs/Vector3[2] ends\nuint64[3] counts\n"),
}

MATRIX = [
    "std_msgs/Header", "std_msgs/Bool", "std_msgs/Int32", "std_msgs/Float32", "std_msgs/String",
    "builtin_interfaces/Time", "geometry_msgs/Twist", "geometry_msgs/TwistStamped",
    "geometry_msgs/Vector3Stamped", "geometry_msgs/PoseStamped", "sensor_msgs/LaserScan",
    "sensor_msgs/Range", "sensor_msgs/Imu", "sensor_msgs/JointState", "sensor_msgs/Joy",
    "sensor_msgs/BatteryState", "nav_msgs/Odometry", "diagnostic_msgs/DiagnosticStatus",
    "diagnostic_msgs/DiagnosticArray", "diagnostic_msgs/KeyValue", "arbc_test/Sized",
]

PRIMITIVES = {"bool", "byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32",
              "int64", "uint64", "float32", "float64", "string"}


class Field:
    """One field of a .msg: its base type (a primitive, or "pkg/Name"), its array shape
    (None, "seq", ("bounded", N) or ("fixed", N)), its name, and the bound of a string<=N
    (0 for none)."""

    def __init__(self, base, shape, name, string_bound=0):
        self.base, self.shape, self.name = base, shape, name
        self.string_bound = string_bound


def fields(full):
    """The fields of message `full` ("pkg/Name"), in order; constants are skipped (they are
    not on the wire) and default values ignored (every field is)."""
    package = full.split("/")[0]
    out = []
    for line in DEFINITIONS[full].splitlines():
        words = line.split()
        if not words or "=" in " ".join(words[1:]):  # NAME=VALUE after the type: a constant
            continue
        word, name = words[0], words[1]
        shape = None
        if "[" in word:
            word, inside = word[:-1].split("[")
            shape = "seq" if not inside else (
                ("bounded", int(inside[2:])) if inside.startswith("<=") else ("fixed", int(inside)))
        bound = 0
        if word.startswith("string<="):
            word, bound = "string", int(word[len("string<="):])
        if word not in PRIMITIVES and "/" not in word:
            word = package + "/" + word
        out.append(Field(word, shape, name, bound))
    return out


def used_in_order(names):
    """Every message `names` use, each after the ones it uses (IDL declares before use)."""
    order = []

    def visit(full):
        if full in order:
            return
        for f in fields(full):
            if f.base not in PRIMITIVES:
                visit(f.base)
        order.append(full)

    for n in names:
        visit(n)
    return order


def write_msg_files(folder):
    """Writes PKG/msg/NAME.msg for every definition under `folder` (a --msg-path folder)."""
    import os
    for full, text in DEFINITIONS.items():
        package, name = full.split("/")
        os.makedirs(os.path.join(folder, package, "msg"), exist_ok=True)
        with open(os.path.join(folder, package, "msg", name + ".msg"), "w") as f:
            f.write(text)
