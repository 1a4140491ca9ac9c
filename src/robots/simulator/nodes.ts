// The robot side of the simulated ROS graph: small "nodes" that publish robot
// state and answer what clients send. Each returns a function that stops it.
import { type Plugin, reachableNames } from "../../core/plugins";
import { began, ROBOT_STATE_TOPIC, type RobotState } from "../../core/robots/robot-state";
import { anglesAt, BODY_JOINTS, gestureBegun, postureChosen, still } from "./body-motion";
import type { RosGraph } from "./graph";

export type RobotNode = (graph: RosGraph, state: RobotState) => () => void;

const ROBOT = "robot";

/**
 * Speech: a std_msgs/String on /speech is "spoken" for msPerChar per
 * character, then "said: <text>" is published on /speech_done (the shape the
 * recorded test node used, so one client works against both): the plugins'
 * completion rule for a say. Anything on /speech_stop silences it at once,
 * and what was cut off is never reported said.
 */
export function speech({
  msPerChar = 60,
  topic = "/speech",
  doneTopic = "/speech_done",
  stopTopic = "/speech_stop",
} = {}): RobotNode {
  return (graph, state) => {
    graph.declare(topic, "std_msgs/msg/String", ROBOT);
    graph.declare(doneTopic, "std_msgs/msg/String", ROBOT);
    graph.declare(stopTopic, "std_msgs/msg/Empty", ROBOT);
    const timers = new Set<NodeJS.Timeout>();
    const silence = graph.listen(stopTopic, () => {
      timers.forEach(clearTimeout);
      timers.clear();
      state.speaking = null;
    });
    const stop = graph.listen(topic, (message) => {
      const text = String(message.data);
      state.speaking = text;
      state.said = began(state.said, text, new Date());
      const timer = setTimeout(() => {
        timers.delete(timer);
        if (state.speaking === text) state.speaking = null;
        state.lastSaid = text;
        graph.publish(doneTopic, { data: `said: ${text}` });
      }, msPerChar * text.length);
      timers.add(timer);
    });
    return () => {
      stop();
      silence();
      timers.forEach(clearTimeout);
    };
  };
}

/**
 * Animations: a std_msgs/String on /animation (its name) runs for
 * `durationMs`, then "done: <name>" is published on /animation_done (the
 * plugins' completion rule for an animation). Anything on /animation_stop
 * ends it at once, never reported done.
 */
export function animation({ durationMs = 1500 } = {}): RobotNode {
  return (graph, state) => {
    graph.declare("/animation", "std_msgs/msg/String", ROBOT);
    graph.declare("/animation_done", "std_msgs/msg/String", ROBOT);
    graph.declare("/animation_stop", "std_msgs/msg/Empty", ROBOT);
    const timers = new Set<NodeJS.Timeout>();
    const stops = [
      graph.listen("/animation", (m) => {
        const name = String(m.data);
        state.animation = name;
        const timer = setTimeout(() => {
          timers.delete(timer);
          if (state.animation === name) state.animation = null;
          graph.publish("/animation_done", { data: `done: ${name}` });
        }, durationMs);
        timers.add(timer);
      }),
      graph.listen("/animation_stop", () => {
        timers.forEach(clearTimeout);
        timers.clear();
        state.animation = null;
      }),
    ];
    return () => {
      stops.forEach((stop) => stop());
      timers.forEach(clearTimeout);
    };
  };
}

/**
 * Sound files: a std_msgs/String on /audio, "<ms> <sha256> <name>" (the
 * simulated plugin's play_audio), "plays" for the file's length, then
 * "played: <name> (<ms> ms)" is published on /audio_done.
 */
export function audio({ topic = "/audio", doneTopic = "/audio_done" } = {}): RobotNode {
  return (graph, state) => {
    graph.declare(topic, "std_msgs/msg/String", ROBOT);
    graph.declare(doneTopic, "std_msgs/msg/String", ROBOT);
    const timers = new Set<NodeJS.Timeout>();
    const stop = graph.listen(topic, (message) => {
      const match = /^(\d+(?:\.\d+)?) ([0-9a-f]{64}) (.+)$/s.exec(String(message.data));
      if (!match) return;
      const playing = { name: match[3]!, durationMs: Number(match[1]) };
      state.playing = playing;
      const timer = setTimeout(() => {
        timers.delete(timer);
        if (state.playing === playing) state.playing = null;
        graph.publish(doneTopic, { data: `played: ${playing.name} (${playing.durationMs} ms)` });
      }, playing.durationMs);
      timers.add(timer);
    });
    return () => {
      stop();
      timers.forEach(clearTimeout);
    };
  };
}

export const stamp = () => {
  const now = Date.now();
  return { sec: Math.floor(now / 1000), nanosec: (now % 1000) * 1_000_000 };
};

/** sensor_msgs/msg/JointState at a fixed rate; `position(n, state)` gives the nth sample. */
export function jointStates({
  hz = 10,
  names = ["head_yaw", "head_pitch"],
  position = (n: number, _: RobotState) => [0.01 * n, -0.5],
  velocity = [0.1, 0],
} = {}): RobotNode {
  return (graph, state) => {
    graph.declare("/joint_states", "sensor_msgs/msg/JointState", ROBOT);
    let n = 0;
    const timer = setInterval(() => {
      n++;
      graph.publish("/joint_states", {
        header: { stamp: stamp(), frame_id: "base_link" },
        name: names,
        position: position(n, state),
        velocity,
        effort: [],
      });
    }, 1000 / hz);
    return () => clearInterval(timer);
  };
}

/**
 * The body's joints on /joint_states at `hz`, moved through each gesture,
 * animation and posture (body-motion.ts), so a joint plot shows what the
 * robot did. A posture is read from the state (a topic or an SSH command may
 * set it); a gesture from its topic, since the same one twice changes no state.
 * A head pitch sent on /joint_angles adds to the posture's.
 */
export function bodyJoints({ hz = 10 } = {}): RobotNode {
  return (graph, state) => {
    let seconds = 0;
    let motion = still(state.posture);
    const begin = (m: Record<string, unknown>) => void (motion = gestureBegun(motion, String(m.data), seconds));
    const stops = [graph.listen("/gesture", begin), graph.listen("/animation", begin)];
    const publisher = jointStates({
      hz,
      names: BODY_JOINTS,
      position: (n, s) => {
        seconds = n / hz;
        if (s.posture !== motion.posture) motion = postureChosen(motion, s.posture, seconds);
        const angles = anglesAt(motion, seconds);
        angles[1]! += s.headPitch;
        return angles;
      },
      velocity: [0, 0, 0, 0],
    })(graph, state);
    return () => {
      stops.forEach((stop) => stop());
      publisher();
    };
  };
}

/**
 * sensor_msgs/msg/BatteryState on /battery, every field, draining 0.01 % per
 * message. What a NAO's battery does not measure is NaN, as the message's
 * definition asks (temperature, design capacity, cells).
 */
export function battery({ hz = 1 } = {}): RobotNode {
  return (graph, state) => {
    graph.declare("/battery", "sensor_msgs/msg/BatteryState", ROBOT);
    const timer = setInterval(() => {
      state.battery = Math.max(0, state.battery - 0.01);
      const percentage = state.battery / 100;
      graph.publish("/battery", {
        header: { stamp: stamp(), frame_id: "" },
        voltage: 21.6 + percentage * 4,
        temperature: Number.NaN,
        current: -1.2,
        charge: percentage * 2.25,
        capacity: 2.25,
        design_capacity: Number.NaN,
        percentage,
        power_supply_status: 2, // discharging
        power_supply_health: 1, // good
        power_supply_technology: 2, // Li-ion
        present: true,
        cell_voltage: [],
        cell_temperature: [],
        location: "body",
        serial_number: "",
      });
    }, 1000 / hz);
    return () => clearInterval(timer);
  };
}

/** Declares every topic a plugin publishes to, and mirrors what arrives into the robot state. */
/**
 * What the robot is doing, as JSON on ROBOT_STATE_TOPIC: the robot view page
 * draws it and speaks its speech. Published on every change (checked at `hz`)
 * and at least once a second.
 */
export function robotStateReport({ hz = 20 } = {}): RobotNode {
  return (graph, state) => {
    graph.declare(ROBOT_STATE_TOPIC, "std_msgs/msg/String", ROBOT);
    let last = "";
    let sentAt = 0;
    const timer = setInterval(() => {
      const now = JSON.stringify(state);
      if (now === last && Date.now() - sentAt < 1000) return;
      sentAt = Date.now();
      graph.publish(ROBOT_STATE_TOPIC, { data: (last = now) });
    }, 1000 / hz);
    return () => clearInterval(timer);
  };
}

export function pluginTopics(plugin: Plugin): RobotNode {
  return (graph, state) => {
    for (const action of plugin.actions) {
      const ros2 = action.ros2;
      if (!ros2 || !("topic" in ros2) || ros2.payloadMapping.type === "ssh") continue;
      // A templated topic under every name its fixed values make; one open to any text is not known before a publish.
      const reach = reachableNames(ros2.topic, action.parameterSchema);
      if ("names" in reach) for (const name of reach.names) graph.declare(name, ros2.messageType, ROBOT);
    }
    const stops = [
      graph.listen("/gesture", (m) => void (state.gesture = String(m.data))),
      graph.listen("/posture", (m) => {
        state.posture = String(m.data);
        state.awake = state.posture !== "rest";
      }),
      graph.listen("/cmd_vel", (m) => {
        const { linear, angular } = m as { linear: { x: number }; angular: { z: number } };
        state.velocity = { linear: linear.x, angular: angular.z };
      }),
      graph.listen("/joint_angles", (m) => {
        const names = m.joint_names as string[];
        const at = names.indexOf("HeadPitch");
        if (at >= 0) state.headPitch = (m.joint_angles as number[])[at]!;
      }),
    ];
    return () => stops.forEach((stop) => stop());
  };
}

/** The services the recorded test node offered (README "ROS side"). */
export function testServices({ slowMs = 3000 } = {}): RobotNode {
  return (graph, state) => {
    graph.offer("/set_led", "std_srvs/srv/SetBool", (r) => ({
      success: true,
      message: `led=${r.data ? "True" : "False"}`,
    }));
    graph.offer("/wake_up", "std_srvs/srv/Trigger", () => {
      Object.assign(state, { posture: "stand", awake: true });
      return { success: true, message: "awake" };
    });
    graph.offer(
      "/slow_op",
      "std_srvs/srv/Trigger",
      () =>
        new Promise((done) =>
          setTimeout(() => done({ success: true, message: `slow done after ${slowMs / 1000} s` }), slowMs),
        ),
    );
    graph.offer("/broken", "std_srvs/srv/Trigger", () => {
      throw new Error("motor fault");
    });
    return () => {};
  };
}

const angleOf = (q: { z: number; w: number }) => 2 * Math.atan2(q.z, q.w);
const wrap = (angle: number) => Math.atan2(Math.sin(angle), Math.cos(angle));

/**
 * nav_msgs/Odometry on /odom at `hz`: the robot's pose, moved by the last
 * /cmd_vel velocity (a differential drive: forward along its heading, turning
 * about z), and its velocity. A wheeled robot's odometry, in the "odom" frame.
 */
export function odometry({ hz = 10 } = {}): RobotNode {
  return (graph, state) => {
    graph.declare("/odom", "nav_msgs/msg/Odometry", ROBOT);
    let last = performance.now();
    const timer = setInterval(() => {
      const now = performance.now();
      const dt = (now - last) / 1000;
      last = now;
      const { linear, angular } = state.velocity;
      const { pose } = state;
      pose.theta = wrap(pose.theta + angular * dt);
      pose.x += linear * Math.cos(pose.theta) * dt;
      pose.y += linear * Math.sin(pose.theta) * dt;
      graph.publish("/odom", {
        header: { stamp: stamp(), frame_id: "odom" },
        child_frame_id: "base_footprint",
        pose: {
          pose: {
            position: { x: pose.x, y: pose.y, z: 0 },
            orientation: { x: 0, y: 0, z: Math.sin(pose.theta / 2), w: Math.cos(pose.theta / 2) },
          },
          covariance: new Array(36).fill(0),
        },
        twist: {
          twist: { linear: { x: linear, y: 0, z: 0 }, angular: { x: 0, y: 0, z: angular } },
          covariance: new Array(36).fill(0),
        },
      });
    }, 1000 / hz);
    return () => clearInterval(timer);
  };
}

/**
 * Nav2's /navigate_to_pose (nav2_msgs/action/NavigateToPose): the robot
 * drives straight to the goal's position at `speed` m/s, sending its pose and
 * the distance left as feedback every `stepMs`, then turns to the goal's
 * heading and succeeds. A cancel stops it where it is.
 */
export function navigation({ speed = 0.5, stepMs = 50 } = {}): RobotNode {
  return (graph, state) => {
    const timers = new Set<NodeJS.Timeout>();
    graph.offerAction("/navigate_to_pose", "nav2_msgs/action/NavigateToPose", (goal, run) => {
      const target = (
        goal.pose as { pose: { position: { x: number; y: number }; orientation: { z: number; w: number } } }
      ).pose;
      const started = Date.now();
      return new Promise((resolve) => {
        const step = () => {
          const { pose } = state;
          const [dx, dy] = [target.position.x - pose.x, target.position.y - pose.y];
          const left = Math.hypot(dx, dy);
          const move = (speed * stepMs) / 1000;
          if (left <= move) {
            Object.assign(pose, { x: target.position.x, y: target.position.y, theta: angleOf(target.orientation) });
            timers.delete(timer);
            return resolve({ error_code: 0, error_msg: "" });
          }
          pose.theta = Math.atan2(dy, dx);
          pose.x += (dx / left) * move;
          pose.y += (dy / left) * move;
          run.feedback({
            current_pose: {
              header: { stamp: stamp(), frame_id: "map" },
              pose: { position: { x: pose.x, y: pose.y, z: 0 } },
            },
            distance_remaining: left - move,
            navigation_time: { sec: Math.floor((Date.now() - started) / 1000), nanosec: 0 },
          });
          timer = setTimeout(step, stepMs);
          timers.add(timer);
        };
        let timer = setTimeout(step, stepMs);
        timers.add(timer);
        void run.cancelled.then(() => {
          clearTimeout(timer);
          timers.delete(timer);
        });
      });
    });
    return () => timers.forEach(clearTimeout);
  };
}
