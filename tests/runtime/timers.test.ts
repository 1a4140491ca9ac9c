// A protocol's time limit, owned by the runtime: a question's "no answer in
// 10 s" pending when the runtime is killed -9 fires after the restart when it
// was due (from its logged start, on the server's clock), once, and a
// runtime opened again after it fired never fires it again. A paused trial's
// limit stands still, across a restart too, and goes on from what it had left
// once resumed. The runtime is the real process; the robot is the simulated one.
import type { ChildProcess } from "node:child_process";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import type { StoredEvent } from "../../src/core/trial";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { eventsSince } from "../../src/store/event-store";
import { studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { trialOf } from "../support/trial-rows";

const SECRET = "timers-test-secret".padEnd(40, "x");

const protocol: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "Timed", description: "", robotId: "simulated" },
  steps: [
    {
      id: "ask",
      name: "Question",
      description: "",
      actions: [
        {
          id: "answer",
          type: "record_answer",
          name: "",
          parameters: { options: [{ id: "yes", label: "Yes" }] },
          parallelGroup: null,
          timeLimit: { seconds: 10, after: { to: "step", stepId: "prompt" } },
        },
      ],
    },
    { id: "prompt", name: "Prompt", description: "", after: { to: "end" }, actions: [] },
  ],
};

/** A 3 s "no answer" limit, for the pause: short, as the test waits through it paused. */
const quick: ProtocolSnapshot = {
  ...protocol,
  experiment: { ...protocol.experiment, name: "Quick" },
  steps: protocol.steps.map((step, i) =>
    i === 0
      ? {
          ...step,
          actions: step.actions.map((a) => ({
            ...a,
            timeLimit: { seconds: 3, after: { to: "step", stepId: "prompt" } },
          })),
        }
      : step,
  ),
};

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
let sim: Simulator;
let wizardId = "";
let trialId = "";
let pausedTrialId = "";
const children: ChildProcess[] = [];
const sockets: TrialSocket[] = [];

beforeAll(async () => {
  const [study] = await db.insert(studies).values({ title: "Timers", status: "active" }).returning();
  wizardId = (
    await createAccount(db, {
      name: "Wizard",
      email: "wizard@timers.example.org",
      password: "password-123",
      role: "researcher",
    })
  ).id;
  await db.insert(studyMembers).values({ studyId: study!.id, userId: wizardId, role: "wizard" });
  trialId = await trialOf(db, { studyId: study!.id, wizardId, snapshot: protocol, withParticipant: true });
  // In a study of its own, with a participant of its own.
  const [other] = await db.insert(studies).values({ title: "Timers paused", status: "active" }).returning();
  await db.insert(studyMembers).values({ studyId: other!.id, userId: wizardId, role: "wizard" });
  pausedTrialId = await trialOf(db, { studyId: other!.id, wizardId, snapshot: quick, withParticipant: true });
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(firstPartyPlugin("simulated.json"), { msPerChar: 0 }) });
}, 60_000);

afterAll(async () => {
  for (const socket of sockets) socket.close();
  for (const child of children) child.kill("SIGKILL");
  await sim?.close();
  await close();
});

/** A runtime of its own, and the wizard's socket to the trial on it (the hello opens the trial). */
async function runtimeWithWizard(trial = trialId) {
  const runtime = await startRuntime(url, SECRET, { HRI_ROSBRIDGE_URL: sim.url });
  children.push(runtime.child);
  const wizard = await connectTrial(runtime.url, signSocketToken({ userId: wizardId, trialId: trial }, SECRET));
  sockets.push(wizard);
  await wizard.next((m) => m.type === "welcome");
  return { runtime, wizard };
}

async function killed(child: ChildProcess) {
  const exited = new Promise((done) => child.once("exit", done));
  child.kill("SIGKILL");
  await exited;
}

const logged = (type: string, events: StoredEvent[]) => events.filter((e) => e.type === type);
const elapse = (ms: number) => new Promise((done) => setTimeout(done, ms));
const firedIn = (m: Record<string, unknown>) =>
  m.type === "events" && (m.events as Array<{ type: string }>).some((e) => e.type === "timer.fired");

describe("a time limit across a runtime restart", () => {
  it("fires when it was due after kill -9, once, and never again", { timeout: 90_000 }, async () => {
    const first = await runtimeWithWizard();
    expect(await first.wizard.command("r1", { kind: "start" })).toMatchObject({ type: "ack" });
    const [started] = logged("timer.started", await eventsSince(db, trialId));
    expect(started).toMatchObject({ timerId: "answer:answer:1", seconds: 10 });
    await killed(first.runtime.child);
    // Nothing fired while no runtime ran: the restart, seconds before the limit, finds it pending.
    expect(logged("timer.fired", await eventsSince(db, trialId))).toEqual([]);

    const second = await runtimeWithWizard();
    await second.wizard.next(
      (m) => m.type === "events" && (m.events as Array<{ type: string }>).some((e) => e.type === "timer.fired"),
      20_000,
    );
    const log = await eventsSince(db, trialId);
    const [fired, ...again] = logged("timer.fired", log);
    expect(again).toEqual([]);
    const late = fired!.serverTime.getTime() - started!.serverTime.getTime() - 10_000;
    expect(late).toBeGreaterThanOrEqual(0);
    expect(late).toBeLessThanOrEqual(100);
    // The protocol's own edge, not a deviation: the trial went on to the prompt, by the time limit.
    expect(log.find((e) => e.seq === fired!.seq + 1)).toMatchObject({
      type: "step.entered",
      stepId: "prompt",
      via: "timeout",
    });
    expect(log.filter((e) => e.deviation)).toEqual([]);
    await killed(second.runtime.child);

    // Opened again after it fired: the fired event in the log wins, nothing is armed.
    const third = await runtimeWithWizard();
    expect(await third.wizard.command("r2", { kind: "note", text: "after the second restart" })).toMatchObject({
      type: "ack",
    });
    const after = await eventsSince(db, trialId);
    expect(logged("timer.fired", after)).toHaveLength(1);
    expect(logged("timer.started", after)).toHaveLength(1);
    // Ended, so that the robot is free for the next trial.
    expect(await third.wizard.command("r3", { kind: "complete" })).toMatchObject({ type: "ack" });
  });
});

describe("a time limit in a paused trial", () => {
  it("stands still while paused, across a restart, and goes on from what it had left", {
    timeout: 90_000,
  }, async () => {
    const first = await runtimeWithWizard(pausedTrialId);
    expect(await first.wizard.command("p1", { kind: "start" })).toMatchObject({ type: "ack" });
    await elapse(500);
    expect(await first.wizard.command("p2", { kind: "pause" })).toMatchObject({ type: "ack" });
    // Paused past the limit's due time: it does not fire.
    await elapse(3_500);
    expect(logged("timer.fired", await eventsSince(db, pausedTrialId))).toEqual([]);
    await killed(first.runtime.child);

    // Opened again paused: nothing is armed.
    const second = await runtimeWithWizard(pausedTrialId);
    await elapse(1_000);
    expect(logged("timer.fired", await eventsSince(db, pausedTrialId))).toEqual([]);
    expect(await second.wizard.command("p3", { kind: "resume" })).toMatchObject({ type: "ack" });
    await second.wizard.next(firedIn, 10_000);

    const log = await eventsSince(db, pausedTrialId);
    const time = (type: string) => logged(type, log)[0]!.serverTime.getTime();
    const [fired, ...again] = logged("timer.fired", log);
    expect(again).toEqual([]);
    // What it had left as the pause began, counted from the resume.
    const left = 3_000 - (time("trial.paused") - time("timer.started"));
    const late = fired!.serverTime.getTime() - time("trial.resumed") - left;
    expect(late).toBeGreaterThanOrEqual(0);
    expect(late).toBeLessThanOrEqual(100);
    expect(log.find((e) => e.seq === fired!.seq + 1)).toMatchObject({ stepId: "prompt", via: "timeout" });
  });
});
