// The built-in simulated robot: a rosbridge v2 server so every path runs without hardware.
import type { Plugin } from "../../core/plugins";
import {
  animation,
  audio,
  battery,
  jointStates,
  pluginTopics,
  robotStateReport,
  speech,
  testServices,
  type RobotNode,
} from "./nodes";

export { startSimulator, type Simulator, type SimulatorOptions, type Received } from "./server";
export * from "./nodes";

const NAO_JOINTS = ["HeadYaw", "HeadPitch", "LShoulderPitch", "RShoulderPitch"];

/** The default robot: the topics of a plugin (NAO6's by default), speech, animations, sound files, joint states and battery. */
export function simulatedRobot(
  plugin: Plugin,
  { msPerChar = 60, jointStatesHz = 10, batteryHz = 1, animationMs = 1500 } = {},
): RobotNode[] {
  return [
    pluginTopics(plugin),
    speech({ msPerChar }),
    animation({ durationMs: animationMs }),
    audio(),
    jointStates({
      hz: jointStatesHz,
      names: NAO_JOINTS,
      position: (_, s) => [0, s.headPitch, 1.4, 1.4],
      velocity: [0, 0, 0, 0],
    }),
    battery({ hz: batteryHz }),
    robotStateReport(),
    testServices(),
  ];
}

/** The ROS side the rosbridge transcripts were recorded against (their README, "ROS side"). */
export function transcriptRobot(): RobotNode[] {
  return [speech({ msPerChar: 0 }), jointStates({ hz: 10 }), testServices()];
}
