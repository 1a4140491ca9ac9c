// The simulated NAO6's SSH side, as the launcher starts it, reached with the
// runtime's real transports: every SSH action of the plugin completes, the
// posture it sets is what the robot page reads over rosbridge, and only the
// launcher's password gets in.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { isSshCommand } from "../../src/core/plugins";
import { ROBOT_STATE_TOPIC, type RobotState } from "../../src/core/robots/robot-state";
import { startDefaultSimulator } from "../../src/robots/simulator/main";
import type { Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { SshTransport } from "../../src/robots/transports/ssh";
import { firstPartyPlugin } from "../support/plugins";

const nao = firstPartyPlugin("nao6-ros2.json");
const action = (id: string) => nao.actions.find((a) => a.id === id)!;
const PASSWORD = "the-launcher-makes-one-per-start";

describe.sequential("the simulated NAO6 over SSH", () => {
  let sim: Simulator;
  let ssh: SshTransport;
  let rosbridge: RosbridgeTransport;
  const published: RobotState[] = [];
  beforeAll(async () => {
    sim = await startDefaultSimulator({ SIM_PORT: "0", SIM_SSH_PORT: "0", SIM_SSH_PASSWORD: PASSWORD });
    ssh = new SshTransport({ host: "127.0.0.1", port: sim.ssh!.port, username: "nao", password: PASSWORD });
    rosbridge = new RosbridgeTransport({ url: sim.url });
    rosbridge.subscribe(ROBOT_STATE_TOPIC, "std_msgs/msg/String", (m) =>
      published.push(JSON.parse((m as { data: string }).data) as RobotState),
    );
    await Promise.all([ssh.connect(), rosbridge.connect()]);
  });
  afterAll(async () => {
    await Promise.all([ssh?.close(), rosbridge?.close()]);
    await sim?.close();
  });

  /** Resolves once the robot page's topic shows the state as it is now. */
  const shown = (want: Partial<RobotState>) =>
    expect.poll(() => published.at(-1), { timeout: 5000 }).toMatchObject(want);

  it("carries out every SSH action of the NAO6 plugin, and shows each posture on the robot's state topic", async () => {
    const postures: Record<string, Partial<RobotState>> = {
      wake_up: { awake: true, posture: "stand" },
      rest: { awake: false, posture: "rest" },
      stand: { awake: true, posture: "stand" },
      stand_init: { awake: true, posture: "stand init" },
      sit: { awake: true, posture: "sit" },
      crouch: { awake: true, posture: "crouch" },
    };
    const ids = nao.actions.filter(isSshCommand).map((a) => a.id);
    expect(ids).toEqual(Object.keys(postures));
    for (const id of ids) {
      expect(await ssh.dispatch(action(id), {})).toEqual({
        status: "completed",
        detail: { exitCode: 0, confirmation: { by: "command_exit", confirmed: true } },
      });
      expect(sim.state).toMatchObject(postures[id]!);
      await shown(postures[id]!);
    }
    expect(sim.ssh!.commands.map((c) => c.command)).toEqual([
      "'qicli' 'call' 'ALMotion.wakeUp'",
      "'qicli' 'call' 'ALMotion.rest'",
      "'qicli' 'call' 'ALRobotPosture.goToPosture' 'Stand' '0.5'",
      "'qicli' 'call' 'ALRobotPosture.goToPosture' 'StandInit' '0.5'",
      "'qicli' 'call' 'ALRobotPosture.goToPosture' 'Sit' '0.5'",
      "'qicli' 'call' 'ALRobotPosture.goToPosture' 'Crouch' '0.5'",
    ]);
  });

  it("keeps one robot state for both sides: a posture published over rosbridge is the one SSH changes", async () => {
    const simulated = firstPartyPlugin("simulated.json");
    const posture = simulated.actions.find((a) => a.id === "posture")!;
    expect(await rosbridge.dispatch(posture, { posture: "rest" })).toMatchObject({ status: "completed" });
    await shown({ posture: "rest", awake: false });
    expect(await ssh.dispatch(action("wake_up"), {})).toMatchObject({ status: "completed" });
    await shown({ posture: "stand", awake: true });
  });

  it("reports what the robot refused in its own words", async () => {
    const dance = {
      ...action("sit"),
      id: "dance",
      ros2: {
        topic: "/ssh",
        messageType: "std_msgs/msg/String",
        payloadMapping: { type: "ssh" as const, sshCommand: "qicli call ALRobotPosture.goToPosture Dance 0.5" },
      },
    };
    expect(await ssh.dispatch(dance, {})).toEqual({
      status: "failed",
      reason:
        'the robot refused the command (exit 1): ALRobotPosture.goToPosture: no posture "Dance" (the robot knows Stand, StandInit, StandZero, Sit, SitRelax, Crouch, LyingBelly, LyingBack)',
    });
  });

  it("lets in no one without the password", async () => {
    const stranger = new SshTransport({ host: "127.0.0.1", port: sim.ssh!.port, username: "nao", password: "guess" });
    await expect(stranger.connect()).rejects.toThrow(`cannot reach nao@127.0.0.1 over SSH`);
    await stranger.close();
  });
});
