// The ROS messages HRIStudio knows the shape of, declared once: the simulated
// robot converts and writes them (src/robots/simulator/ros-types.ts) and the
// plugin loader checks that an event's condition reads fields its message has.
// Keys are "pkg/Type"; ROS 2's "pkg/msg/Type" names the same type.

/** A field's type: a primitive, a message key, or either with "[]". */
export type Field = string;
export type Definition = Record<string, Field>;

export const MESSAGES: Record<string, Definition> = {
  "std_msgs/String": { data: "string" },
  "std_msgs/Bool": { data: "bool" },
  "std_msgs/Int32": { data: "int32" },
  "std_msgs/Float32": { data: "float32" },
  "std_msgs/Float64": { data: "float64" },
  "std_msgs/Empty": {},
  "std_msgs/Header": { stamp: "builtin_interfaces/Time", frame_id: "string" },
  "builtin_interfaces/Time": { sec: "int32", nanosec: "uint32" },
  "geometry_msgs/Vector3": { x: "float64", y: "float64", z: "float64" },
  "geometry_msgs/Twist": { linear: "geometry_msgs/Vector3", angular: "geometry_msgs/Vector3" },
  "geometry_msgs/Point": { x: "float64", y: "float64", z: "float64" },
  "geometry_msgs/Quaternion": { x: "float64", y: "float64", z: "float64", w: "float64" },
  "geometry_msgs/Pose": { position: "geometry_msgs/Point", orientation: "geometry_msgs/Quaternion" },
  "geometry_msgs/PoseStamped": { header: "std_msgs/Header", pose: "geometry_msgs/Pose" },
  "geometry_msgs/PoseWithCovariance": { pose: "geometry_msgs/Pose", covariance: "float64[]" },
  "geometry_msgs/TwistWithCovariance": { twist: "geometry_msgs/Twist", covariance: "float64[]" },
  "nav_msgs/Odometry": {
    header: "std_msgs/Header",
    child_frame_id: "string",
    pose: "geometry_msgs/PoseWithCovariance",
    twist: "geometry_msgs/TwistWithCovariance",
  },
  "sensor_msgs/JointState": {
    header: "std_msgs/Header",
    name: "string[]",
    position: "float64[]",
    velocity: "float64[]",
    effort: "float64[]",
  },
  // Every field of ROS 2's sensor_msgs/msg/BatteryState, in its order.
  "sensor_msgs/BatteryState": {
    header: "std_msgs/Header",
    voltage: "float32",
    temperature: "float32",
    current: "float32",
    charge: "float32",
    capacity: "float32",
    design_capacity: "float32",
    percentage: "float32",
    power_supply_status: "uint8",
    power_supply_health: "uint8",
    power_supply_technology: "uint8",
    present: "bool",
    cell_voltage: "float32[]",
    cell_temperature: "float32[]",
    location: "string",
    serial_number: "string",
  },
  // data: uint8[], which rosbridge's JSON carries as one base64 string.
  "sensor_msgs/CompressedImage": { header: "std_msgs/Header", format: "string", data: "uint8[]" },
  "naoqi_bridge_msgs/JointAnglesWithSpeed": {
    header: "std_msgs/Header",
    joint_names: "string[]",
    joint_angles: "float32[]",
    speed: "float32",
    relative: "uint8",
  },
  // What NAO and Pepper sense, as naoqi_driver2 publishes it (naoqi_bridge_msgs; the constants are the
  // messages' own: a HeadTouch button 1 front, 2 middle, 3 rear; a HandTouch hand 0..2 right, 3..5 left;
  // a Bumper 0 right, 1 left; every state 0 released, 1 pressed).
  "naoqi_bridge_msgs/HeadTouch": { button: "uint8", state: "uint8" },
  "naoqi_bridge_msgs/HandTouch": { hand: "uint8", state: "uint8" },
  "naoqi_bridge_msgs/Bumper": { bumper: "uint8", state: "uint8" },
  // The speech recogniser's words, each with its confidence (0..1), in the same order.
  "naoqi_bridge_msgs/WordRecognized": { words: "string[]", confidence_values: "float32[]" },
  // ROS 2 Humble's sensor_msgs/msg/Range (a sonar); radiation_type 0 is ultrasound.
  "sensor_msgs/Range": {
    header: "std_msgs/Header",
    radiation_type: "uint8",
    field_of_view: "float32",
    min_range: "float32",
    max_range: "float32",
    range: "float32",
  },
  "sensor_msgs/LaserScan": {
    header: "std_msgs/Header",
    angle_min: "float32",
    angle_max: "float32",
    angle_increment: "float32",
    time_increment: "float32",
    scan_time: "float32",
    range_min: "float32",
    range_max: "float32",
    ranges: "float32[]",
    intensities: "float32[]",
  },
  // TurtleBot3's OpenCR board: bumper 1 forward, 2 backward (turtlebot3_msgs' BUMPER_FORWARD, BUMPER_BACKWARD).
  "turtlebot3_msgs/SensorState": {
    header: "std_msgs/Header",
    bumper: "uint8",
    cliff: "float32",
    sonar: "float32",
    illumination: "float32",
    led: "uint8",
    button: "uint8",
    torque: "bool",
    left_encoder: "int32",
    right_encoder: "int32",
    battery: "float32",
  },
};

/** The key of a message type, "pkg/msg/Type" or "pkg/Type"; null when it is not a message type name. */
export function messageKey(type: string): string | null {
  const parts = type.split("/");
  if (parts.length < 2 || parts.length > 3 || parts.some((p) => !p) || (parts.length === 3 && parts[1] !== "msg"))
    return null;
  return `${parts[0]}/${parts[parts.length - 1]}`;
}

/** Whether HRIStudio knows the fields of this message type. */
export function knownMessage(type: string): boolean {
  const key = messageKey(type);
  return key !== null && Object.hasOwn(MESSAGES, key);
}

/** The type of the field at a dotted path of a known message ("header.stamp.sec"), or null when it has none. */
export function fieldType(type: string, path: string): Field | null {
  let field: Field | undefined = messageKey(type) ?? undefined;
  for (const name of path.split(".")) {
    const definition = field === undefined ? undefined : MESSAGES[field];
    if (!definition || !Object.hasOwn(definition, name)) return null;
    field = definition[name];
  }
  return field ?? null;
}
