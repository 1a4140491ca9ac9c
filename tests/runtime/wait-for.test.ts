// What the robot senses, handed to the trial's host (its `sensed` entry
// point): it goes through the host's one queue into the log, so a pending
// "Wait for" moves once, an event with nothing waiting is logged and changes
// nothing, and a wizard's go on and an event that come together move the
// trial once. The runtime's trial hosts, the real log, locks and robot link
// against the simulated robot.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import type { StoredEvent } from "../../src/core/trial";
import { createAccount } from "../../src/server/auth/accounts";
import { eventsSince } from "../../src/store/event-store";
import { studies } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { simulatedHosts } from "../support/simulated-hosts";
import { rehearsalOf, trialOf } from "../support/trial-rows";

const plugin = firstPartyPlugin("simulated.json");

// "Touch my head to start": head touched → Greet; the wizard's go on → Goodbye, the step's own way on.
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
    { id: "bye", name: "Goodbye", description: "", after: { to: "end" }, actions: [] },
    { id: "greet", name: "Greet", description: "", after: { to: "end" }, actions: [] },
  ],
};

const touched = { event: "head_touched", at: 1_800_000_000_250, message: { data: true } };

const { db, url, close } = await freshDatabase();
const { hosts, close: closeHosts } = await simulatedHosts(db, url, plugin);
let studyId = "";
let wizardId = "";

beforeAll(async () => {
  const [study] = await db.insert(studies).values({ title: "Waits", status: "active" }).returning();
  studyId = study!.id;
  wizardId = (
    await createAccount(db, {
      name: "Wizard",
      email: "wizard@waits.example.org",
      password: "password-123",
      role: "researcher",
    })
  ).id;
}, 60_000);

afterAll(async () => {
  await closeHosts();
  await close();
});

/** A rehearsal of the protocol, open on its host and started: the wait is pending. */
async function waitingTrial() {
  const trialId = await rehearsalOf(db, studyId, protocol);
  const host = (await hosts.get(trialId))!;
  expect(await host.command({ kind: "start" }, wizardId)).toMatchObject({ ok: true });
  return { trialId, host };
}

const from = (log: StoredEvent[], type: string) => log.slice(log.findIndex((e) => e.type === type));
const brief = (events: StoredEvent[]) =>
  events.map((e) => (e.type === "step.entered" ? `${e.type} ${e.stepId} ${e.via}` : e.type));

describe("the robot's senses on a live trial", () => {
  it("an awaited event moves the pending wait once, with the robot's time in the log", async () => {
    const { trialId, host } = await waitingTrial();
    expect(await host.sensed(touched)).toMatchObject({ ok: true });
    expect(await host.sensed({ ...touched, at: touched.at + 500 })).toMatchObject({ ok: true });
    const log = await eventsSince(db, trialId);
    expect(brief(from(log, "robot.sensed"))).toEqual([
      "robot.sensed",
      "wait.resolved",
      "step.entered greet sensed",
      "robot.sensed",
    ]);
    expect(log.find((e) => e.type === "robot.sensed")).toMatchObject({
      event: "head_touched",
      at: touched.at,
      message: { data: true },
      actorId: null,
    });
    expect(host.current.currentStepId).toBe("greet");
  });

  it("an event with nothing waiting for it is logged and changes nothing", async () => {
    const { trialId, host } = await waitingTrial();
    const before = host.current;
    expect(await host.sensed({ event: "left_hand_touched", at: touched.at, message: { data: true } })).toMatchObject({
      ok: true,
    });
    const log = await eventsSince(db, trialId);
    expect(brief(from(log, "robot.sensed"))).toEqual(["robot.sensed"]);
    expect(host.current.currentStepId).toBe("ask");
    expect(host.current.actions.wait).toEqual(before.actions.wait);
  });

  it("a go on and an event sent together move the trial exactly once", async () => {
    for (const goOnFirst of [true, false]) {
      const { trialId, host } = await waitingTrial();
      const goOn = () => host.command({ kind: "go_on" }, wizardId);
      const [first, second] = goOnFirst
        ? await Promise.all([goOn(), host.sensed(touched)])
        : await Promise.all([host.sensed(touched), goOn()]);
      expect(first).toMatchObject({ ok: true });
      const log = await eventsSince(db, trialId);
      const entered = log.filter((e) => e.type === "step.entered" && e.via !== "start");
      expect(entered).toHaveLength(1);
      expect(log.filter((e) => e.type === "wait.resolved")).toHaveLength(1);
      if (goOnFirst) {
        // The event after the go on: the robot's observation only.
        expect(second).toMatchObject({ ok: true });
        expect(brief(entered)).toEqual(["step.entered bye go_on"]);
        expect(log.find((e) => e.type === "wait.resolved")).toMatchObject({ by: "wizard", actorId: wizardId });
      } else {
        expect(second).toMatchObject({ ok: false, reason: expect.stringContaining("the wait is already over") });
        expect(brief(entered)).toEqual(["step.entered greet sensed"]);
      }
    }
  });

  it("a published trial waiting for an event its robot does not sense is refused at its start, with the reason", async () => {
    // The simulated robot senses what a NAO6 does: a wagged tail is no event of its.
    const wagged = JSON.parse(JSON.stringify(protocol).replace('"head_touched"', '"tail_wagged"')) as ProtocolSnapshot;
    const trialId = await trialOf(db, { studyId, wizardId, snapshot: wagged, withParticipant: true });
    await expect(hosts.get(trialId)).rejects.toThrow(/does not sense "tail_wagged"/);
  });
});
