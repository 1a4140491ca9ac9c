// The simulated robot's camera: sensor_msgs/CompressedImage on the topic the
// plugins declare, cycling through a few small precomputed JPEGs
// (scripts/simulator-camera-frames.mjs makes them). Published at the camera's
// own rate; rosbridge's throttle_rate decides what each subscriber gets.
import recorded from "./camera-frames.json";
import { type RobotNode, stamp } from "./nodes";

export const CAMERA_TOPIC = "/camera/front/image_raw/compressed";

export function camera({ hz = 15, topic = CAMERA_TOPIC } = {}): RobotNode {
  return (graph) => {
    graph.declare(topic, "sensor_msgs/msg/CompressedImage", "robot");
    let n = 0;
    const timer = setInterval(() => {
      // uint8[] travels as base64 in rosbridge's JSON, as a real bridge sends it.
      graph.publish(topic, {
        header: { stamp: stamp(), frame_id: "camera_front" },
        format: recorded.format,
        data: recorded.frames[n++ % recorded.frames.length],
      });
    }, 1000 / hz);
    return () => clearInterval(timer);
  };
}
