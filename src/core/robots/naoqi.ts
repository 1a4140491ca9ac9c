// The NAOqi side of the simulated robot: what a NAO answers to the qicli
// commands plugins send over SSH, and what it does to the robot's state. The
// simulator's SSH server runs each exec through this; the same state is what
// its rosbridge side publishes, so the robot page shows a posture set either way.
import { shellWords } from "../plugins/shell";
import type { RobotState } from "./robot-state";

export interface NaoqiReply {
  exitCode: number;
  stdout: string;
  stderr: string;
  /** What the command changed on the robot. */
  change: Partial<RobotState>;
}

/** ALRobotPosture's predefined postures (NAO6), as the robot page names them. */
export const NAOQI_POSTURES: Record<string, string> = {
  Stand: "stand",
  StandInit: "stand init",
  StandZero: "stand zero",
  Sit: "sit",
  SitRelax: "sit relax",
  Crouch: "crouch",
  LyingBelly: "lying on its front",
  LyingBack: "lying on its back",
};

const done = (change: Partial<RobotState>, stdout = ""): NaoqiReply => ({ exitCode: 0, stdout, stderr: "", change });
const refused = (exitCode: number, stderr: string): NaoqiReply => ({
  exitCode,
  stdout: "",
  stderr: `${stderr}\n`,
  change: {},
});

/** The methods the simulated NAO offers, by "Service.method", given their arguments. */
const METHODS: Record<string, (args: string[]) => NaoqiReply> = {
  // Motors on; a robot at rest stands up, as ALMotion.wakeUp does.
  "ALMotion.wakeUp": () => done({ awake: true, posture: "stand" }),
  // Crouched with its motors off.
  "ALMotion.rest": () => done({ awake: false, posture: "rest" }),
  // Going to a posture wakes the robot first; the speed must be a fraction of the maximum.
  "ALRobotPosture.goToPosture": ([name, speed]) => {
    const posture = NAOQI_POSTURES[name ?? ""];
    if (!posture)
      return refused(
        1,
        `ALRobotPosture.goToPosture: no posture "${name ?? ""}" (the robot knows ${Object.keys(NAOQI_POSTURES).join(", ")})`,
      );
    const fraction = Number(speed);
    if (speed === undefined || !(fraction > 0 && fraction <= 1))
      return refused(
        1,
        `ALRobotPosture.goToPosture: the speed must be a number above 0 and at most 1, not "${speed ?? ""}"`,
      );
    return done({ awake: true, posture }, "true\n");
  },
};

/** Runs one command line as the simulated NAO's shell would. */
export function naoqiCommand(command: string): NaoqiReply {
  const parsed = shellWords(command);
  if (!parsed.ok) return refused(2, `sh: the simulated robot runs one plain command: ${parsed.reason}`);
  const [program, verb, method, ...args] = parsed.words;
  if (program === undefined) return done({});
  if (program !== "qicli") return refused(127, `sh: ${program}: not found (the simulated robot has only qicli)`);
  if (verb !== "call" || !method)
    return refused(1, "qicli: the simulated robot answers only `qicli call Service.method ...`");
  const run = METHODS[method];
  if (!run)
    return refused(
      1,
      `qicli: the simulated robot has no method ${method} (it offers ${Object.keys(METHODS).join(", ")})`,
    );
  return run(args);
}
