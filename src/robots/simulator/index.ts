// The built-in simulated robot: a rosbridge v2 server so every path runs without hardware.
import type { Plugin } from "../../core/plugins";
import {
  animation,
  audio,
  battery,
  bodyJoints,
  jointStates,
  navigation,
  odometry,
  pluginTopics,
  robotStateReport,
  speech,
  testServices,
  type RobotNode,
} from "./nodes";
import { camera } from "./camera";
import { pluginServices } from "./plugin-services";
import { senses } from "./senses";

export { startSimulator, type Simulator, type SimulatorOptions, type Received } from "./server";
export * from "./nodes";
export { camera, CAMERA_TOPIC } from "./camera";

/** Whether the plugin drives a base (velocity commands or navigation goals): its robot then has odometry and Nav2's navigation. */
const drives = (plugin: Plugin) =>
  plugin.actions.some((a) => a.ros2 && (("topic" in a.ros2 && a.ros2.topic === "/cmd_vel") || "action" in a.ros2));

/** The default robot: the topics of a plugin (NAO6's by default), speech, animations, sound files, joint states, battery, its camera and what it senses; odometry and navigation for a robot that drives. */
export function simulatedRobot(
  plugin: Plugin,
  { msPerChar = 60, jointStatesHz = 10, batteryHz = 1, animationMs = 1500 } = {},
): RobotNode[] {
  return [
    ...(drives(plugin) ? [odometry(), navigation()] : []),
    pluginTopics(plugin),
    pluginServices(plugin),
    speech({ msPerChar }),
    animation({ durationMs: animationMs }),
    audio(),
    bodyJoints({ hz: jointStatesHz }),
    battery({ hz: batteryHz }),
    camera(),
    senses(plugin),
    robotStateReport(),
    testServices(),
  ];
}

/** The ROS side the rosbridge transcripts were recorded against (their README, "ROS side"). */
export function transcriptRobot(): RobotNode[] {
  return [speech({ msPerChar: 0 }), jointStates({ hz: 10 }), testServices()];
}
