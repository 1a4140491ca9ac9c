// Every action of the NAO6 plugin on the default simulated NAO6, as `npm
// start` runs it with no robot settings: the designer calls each runnable, and
// a rehearsal through the real runtime completes each, one after another; the
// postures sent over SSH show on the robot's state topic, as the robot page
// reads it. Then the same robot named as a real one with no SSH address: the
// designer and the runtime agree, action by action, on what cannot run, and why.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { portability, robotActionType, withDefaults, type Channels, type Plugin } from "../../src/core/plugins";
import { ROBOT_STATE_TOPIC, type RobotState } from "../../src/core/robots/robot-state";
import { fold, type TrialEvent, type TrialProtocol } from "../../src/core/trial";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";
import { connectTrial, type TrialSocket } from "../support/socket";

const ROBOT = "nao6-ros2";
// What a researcher would type into the forms the designer shows empty.
const EXAMPLES: Record<string, string> = {
  text: "Hello, I am NAO.",
  name: "animations/Stand/Gestures/Hey_1",
};
const ENDED = ["action.completed", "action.failed", "action.timed_out"];
const NAOQI = ["wake_up", "rest", "stand", "stand_init", "sit", "crouch"];

const eventsOf = (socket: TrialSocket) => {
  const bySeq = new Map<number, TrialEvent>();
  for (const m of socket.messages)
    for (const e of (m.events as TrialEvent[] | undefined) ?? []) bySeq.set((e as { seq: number }).seq, e);
  return [...bySeq.values()];
};
const endOf = (events: TrialEvent[], actionId: string) =>
  events.find((e) => ENDED.includes(e.type) && "actionId" in e && e.actionId === actionId);

/** A rehearsal of one step holding every action of the NAO6 plugin, in its order, as the designer fills their forms. */
async function rehearseEveryAction(app: RunningApp) {
  const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
  const nao = (await researcher.plugins.get.query({ robotId: ROBOT })) as Plugin;
  const [study] = await researcher.studies.mine.query();
  const experiment = await researcher.experiments.create.mutate({
    studyId: study!.id,
    name: "Every NAO6 action",
    robotId: ROBOT,
  });
  const actions = nao.actions.map((a) => {
    const required = (a.parameterSchema.required ?? []).filter((key) => EXAMPLES[key]);
    const filled = Object.fromEntries(required.map((key) => [key, EXAMPLES[key]]));
    return { type: robotActionType(ROBOT, a.id), name: a.name, parameters: withDefaults(a.parameterSchema, filled) };
  });
  await researcher.experiments.saveDesign.mutate({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "Every action", actions }],
  });
  const trialId = (await researcher.trials.rehearse.mutate({ experimentId: experiment.id })).id;
  const protocol = (await researcher.trials.get.query({ trialId })).protocol as TrialProtocol;
  expect(protocol.steps[0]!.actions.map((a) => a.type)).toEqual(nao.actions.map((a) => robotActionType(ROBOT, a.id)));
  const { channels } = await researcher.plugins.list.query();
  return { researcher, nao, trialId, protocol, channels: channels as Channels };
}

/** What the designer says of each action on this server: "runs", or why not. */
const designerSays = (r: Awaited<ReturnType<typeof rehearseEveryAction>>) =>
  portability(r.protocol, r.nao, r.channels).actions.map((a): [string, string] => [
    a.pluginAction!,
    a.status === "supported" ? "runs" : `cannot run: ${a.reason}`,
  ]);

/**
 * The wizard presses N for each action once the one before has ended, and
 * sees how it ended; `after` looks at the robot after each.
 */
async function walk(r: Awaited<ReturnType<typeof rehearseEveryAction>>, after?: (actionType: string) => Promise<void>) {
  const { url, token } = await r.researcher.trials.socketToken.mutate({ trialId: r.trialId });
  const wizard = await connectTrial(url, token);
  expect(await wizard.command("start", { kind: "start" })).toMatchObject({ type: "ack" });
  const outcomes: Array<[string, string]> = [];
  for (const [n, action] of r.protocol.steps[0]!.actions.entries()) {
    expect(await wizard.command(`next-${n}`, { kind: "next" })).toMatchObject({ type: "ack" });
    await wizard.next(() => endOf(eventsOf(wizard), action.id) !== undefined, 20_000);
    const ended = endOf(eventsOf(wizard), action.id)!;
    outcomes.push([
      r.nao.actions[n]!.id,
      ended.type === "action.completed" ? "runs" : ended.type === "action.failed" ? ended.reason : ended.type,
    ]);
    await after?.(action.type);
  }
  const events = eventsOf(wizard);
  wizard.close();
  return { outcomes, state: fold(r.protocol, events) };
}

describe.sequential("every action of the NAO6 plugin on the default simulated NAO6", () => {
  let app: RunningApp;
  let demo: Awaited<ReturnType<typeof rehearseEveryAction>>;

  beforeAll(async () => {
    app = await startApp();
    demo = await rehearseEveryAction(app);
  });
  afterAll(async () => app?.stop());

  it("the designer calls every one of them runnable on this server", () => {
    expect(demo.channels).toEqual({ rosbridge: true, simulator: true, ssh: true, http: false });
    expect(designerSays(demo)).toEqual(demo.nao.actions.map((a) => [a.id, "runs"]));
  });

  it("completes each of them in a rehearsal through the runtime, and the robot shows the postures", async () => {
    const robotPage = new RosbridgeTransport({ url: app.simulatorUrl });
    const shown: RobotState[] = [];
    robotPage.subscribe(ROBOT_STATE_TOPIC, "std_msgs/msg/String", (m) =>
      shown.push(JSON.parse((m as { data: string }).data) as RobotState),
    );
    await robotPage.connect();
    const postures: Record<string, Partial<RobotState>> = {
      [robotActionType(ROBOT, "rest")]: { posture: "rest", awake: false },
      [robotActionType(ROBOT, "sit")]: { posture: "sit", awake: true },
      [robotActionType(ROBOT, "crouch")]: { posture: "crouch", awake: true },
    };
    const { outcomes, state } = await walk(demo, async (type) => {
      if (postures[type]) await expect.poll(() => shown.at(-1), { timeout: 5000 }).toMatchObject(postures[type]!);
    });
    expect(outcomes).toEqual(demo.nao.actions.map((a) => [a.id, "runs"]));
    expect(Object.values(state.actions).map((a) => a.status)).toEqual(demo.nao.actions.map(() => "done"));
    await robotPage.close();
  });

  it("named as a real robot with no SSH address, the designer and the runtime agree on what cannot run, and why", async () => {
    const real = await startApp({ env: { HRI_ROSBRIDGE_URL: app.simulatorUrl } });
    try {
      const r = await rehearseEveryAction(real);
      expect(r.channels).toEqual({ rosbridge: true, simulator: true, ssh: false, http: false });
      const says = designerSays(r);
      expect(says.filter(([, verdict]) => verdict !== "runs").map(([id]) => id)).toEqual(NAOQI);
      const { outcomes } = await walk(r);
      // The runtime's words are the designer's, with the action and robot named.
      expect(outcomes).toEqual(
        says.map(([id, verdict]) => {
          const action = r.nao.actions.find((a) => a.id === id)!;
          return [
            id,
            verdict === "runs"
              ? "runs"
              : `"${action.name}" ${verdict.replace("cannot run:", `cannot run on ${r.nao.name}:`)}`,
          ];
        }),
      );
      expect(outcomes.find(([id]) => id === "sit")![1]).toBe(
        `"Sit" cannot run on ${r.nao.name}: it needs SSH to the robot, and this server has no SSH address for it: set HRI_ROBOT_SSH_HOST (see docs/robot-setup.md)`,
      );
    } finally {
      await real.stop();
    }
  });
});
