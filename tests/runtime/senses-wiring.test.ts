// What the robot senses, end to end on the runtime: a stimulus published on
// the simulated robot (as its Robot page does) is a real message on the
// event's topic, the trial host's watcher (RobotLink.watchSenses) matches it,
// and the trial moves. The runtime's trial hosts, the real log and a real
// rosbridge connection to the simulated robot; nothing handed in by hand.
import * as ROSLIB from "roslib";
import { afterAll, beforeAll, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import type { StoredEvent } from "../../src/core/trial";
import { type Stimulus, STIMULUS_TOPIC } from "../../src/core/robots/stimulus";
import { createAccount } from "../../src/server/auth/accounts";
import { eventsSince } from "../../src/store/event-store";
import { studies } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { simulatedHosts } from "../support/simulated-hosts";
import { rehearsalOf } from "../support/trial-rows";

const plugin = firstPartyPlugin("simulated.json");

// "Touch my head to start": head touched → Greet.
const protocol: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "Touch to start", description: "", robotId: "simulated" },
  steps: [
    {
      id: "ask",
      name: "Ask",
      description: "",
      actions: [
        {
          id: "wait",
          type: "wait_for",
          name: "",
          parameters: { events: [{ id: "t", event: "head_touched", after: { to: "step", stepId: "greet" } }] },
          parallelGroup: null,
        },
      ],
    },
    { id: "greet", name: "Greet", description: "", after: { to: "end" }, actions: [] },
  ],
};

const { db, url, close } = await freshDatabase();
const { sim, hosts, close: closeHosts } = await simulatedHosts(db, url, plugin);
let page: ROSLIB.Ros;
let studyId = "";
let wizardId = "";

beforeAll(async () => {
  page = new ROSLIB.Ros({ url: sim.url });
  await new Promise<void>((ok, fail) => {
    page.on("connection", () => ok());
    page.on("error", (e) => fail(new Error(`Could not reach the simulated robot at ${sim.url}: ${String(e)}`)));
  });
  const [study] = await db.insert(studies).values({ title: "Senses", status: "active" }).returning();
  studyId = study!.id;
  wizardId = (
    await createAccount(db, {
      name: "Wizard",
      email: "wizard@senses.example.org",
      password: "password-123",
      role: "researcher",
    })
  ).id;
}, 60_000);

afterAll(async () => {
  page?.close();
  await closeHosts();
  await close();
});

/** The Robot page's control: a stimulus as JSON on the simulator's stimulus topic. */
const fire = (stimulus: Stimulus) =>
  new ROSLIB.Topic({ ros: page, name: STIMULUS_TOPIC, messageType: "std_msgs/msg/String" }).publish({
    data: JSON.stringify(stimulus),
  });

/** How many subscriptions the simulator has had to a topic: the trial's watcher, our listener. */
const subscriptions = (topic: string) =>
  sim.received.filter((r) => {
    const m = r.message as { op?: string; topic?: string };
    return m.op === "subscribe" && m.topic === topic;
  }).length;

/** Every message published on the head's touch topic, as the page would see them. */
function headMessages() {
  const messages: Array<Record<string, unknown>> = [];
  new ROSLIB.Topic({ ros: page, name: "/head_touch", messageType: "naoqi_bridge_msgs/msg/HeadTouch" }).subscribe((m) =>
    messages.push(m as Record<string, unknown>),
  );
  return messages;
}

/** A rehearsal of the protocol, open on its host and started, its robot watching the head: the wait is pending. */
async function waitingTrial() {
  const trialId = await rehearsalOf(db, studyId, protocol);
  const watching = subscriptions("/head_touch");
  const host = (await hosts.get(trialId))!;
  await expect.poll(() => subscriptions("/head_touch"), { timeout: 10_000 }).toBeGreaterThan(watching);
  expect(await host.command({ kind: "start" }, wizardId)).toMatchObject({ ok: true });
  return { trialId, host };
}

/** What moved the trial, and what the robot sensed, in order. */
const SHOWN = new Set(["step.entered", "robot.sensed", "wait.resolved"]);
const brief = (events: StoredEvent[]) =>
  events
    .filter((e) => SHOWN.has(e.type))
    .map((e) => (e.type === "step.entered" ? `${e.type} ${e.stepId} ${e.via}` : e.type));

it("a head touch fired on the simulated robot moves the waiting trial once; its release changes nothing", async () => {
  const { trialId, host } = await waitingTrial();
  const head = headMessages();
  await expect.poll(() => subscriptions("/head_touch"), { timeout: 10_000 }).toBeGreaterThan(1);
  const before = Date.now();
  fire({ event: "head_touched", touch: true });
  // The press and then its release, both published: whatever the release could do, it has had its chance.
  await expect.poll(() => head.length, { timeout: 10_000 }).toBe(2);
  await expect
    .poll(async () => brief(await eventsSince(db, trialId)), { timeout: 10_000 })
    .toEqual(["step.entered ask start", "robot.sensed", "wait.resolved", "step.entered greet sensed"]);
  const log = await eventsSince(db, trialId);
  const sensed = log.find((e) => e.type === "robot.sensed");
  // A HeadTouch has no stamp: the runtime's clock on arrival stands for the robot's.
  expect(sensed).toMatchObject({ event: "head_touched", message: { button: 2, state: 1 }, actorId: null });
  expect((sensed as { at: number }).at).toBeGreaterThanOrEqual(before);
  expect(log.find((e) => e.type === "wait.resolved")).toMatchObject({ by: "sensed" });
  expect(host.current.currentStepId).toBe("greet");
});

it("a touch with nothing waiting for it is logged as the robot's observation and changes nothing", async () => {
  const { trialId, host } = await waitingTrial();
  const before = host.current;
  fire({ event: "left_hand_touched", touch: true });
  await expect
    .poll(async () => (await eventsSince(db, trialId)).filter((e) => e.type === "robot.sensed").length, {
      timeout: 10_000,
    })
    .toBe(1);
  const log = await eventsSince(db, trialId);
  expect(log.find((e) => e.type === "robot.sensed")).toMatchObject({ event: "left_hand_touched" });
  expect(brief(log)).toEqual(["step.entered ask start", "robot.sensed"]);
  expect(host.current.currentStepId).toBe("ask");
  expect(host.current.actions.wait).toEqual(before.actions.wait);
});
