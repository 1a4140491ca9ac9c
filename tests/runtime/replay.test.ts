// Replay, end to end: a real trial run by a wizard through the real runtime
// against the simulated NAO6, then replayed by an observer. The simulated
// robot must receive the same messages (exact payloads) in the same order,
// with the gaps it received them at in the live run (±50 ms), halved at ×2;
// a replay from a moment leaves out what came before; and the trial's log is
// byte for byte what it was.
//
// The original gaps are the simulator's own receipt times in the live run,
// not the log's dispatch times the replay is scheduled from: what the robot
// received is the thing a replay must reproduce, so the test measures the
// replay against it (the dispatch times stand in for it, and this checks they do).
import { asc, eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { REPLAY_TOPIC } from "../../src/core/robots/robot-state";
import { DOCUMENT_VERSION } from "../../src/core/protocol/document";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import {
  experimentVersions,
  experiments,
  robots,
  studies,
  studyMembers,
  trialEvents,
  trials,
} from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { firstPartyPlugin } from "../support/plugins";

const SECRET = "replay-test-secret".padEnd(40, "x");
const TOLERANCE_MS = 50;
const ROBOT_TOPICS = ["/speech", "/animation", "/joint_angles"];
const nao = firstPartyPlugin("nao6-ros2.json");

const action = (
  id: string,
  type: string,
  parameters: Record<string, unknown> = {},
  parallelGroup: string | null = null,
) => ({
  id,
  type,
  name: id,
  parameters,
  parallelGroup,
});
// Speech, a gesture with speech at the same moment, a wizard's note, then two more commands.
const protocol = {
  schemaVersion: DOCUMENT_VERSION as typeof DOCUMENT_VERSION,
  experiment: { id: "replay-experiment", name: "Replayed", description: "", robotId: "nao6-ros2" },
  steps: [
    {
      id: "greet",
      name: "Greet",
      description: "",
      actions: [
        action("hello", "say", { text: "Hello, I am NAO." }),
        action("hey", "nao6-ros2.play_animation_hey", {}, "together"),
        action("look", "say", { text: "Look at this!" }, "together"),
        action("note", "wizard_instruction", { text: "Smile" }),
      ],
    },
    {
      id: "part",
      name: "Part",
      description: "",
      actions: [action("down", "nao6-ros2.look_down"), action("bye", "nao6-ros2.say_text", { text: "Goodbye." })],
    },
  ],
};
// The wizard's pauses after each press of N (hello, the group, the note, on to
// Part, down, goodbye, the end), so the gaps are uneven.
const PAUSES_MS = [350, 700, 150, 50, 500, 250, 0];

interface Heard {
  at: number;
  topic: string;
  msg: unknown;
}
/** What the simulated robot received on the robot's own topics since `from` (an index into its record). */
const heardSince = (sim: Simulator, from: number): Heard[] =>
  sim.received
    .slice(from)
    .filter((r) => r.message.op === "publish" && ROBOT_TOPICS.includes(String(r.message.topic)))
    .map((r) => ({ at: r.at, topic: String(r.message.topic), msg: r.message.msg }));
const gaps = (heard: Heard[]) => heard.slice(1).map((h, i) => h.at - heard[i]!.at);
const content = (heard: Heard[]) => heard.map(({ topic, msg }) => ({ topic, msg }));

describe.sequential("a finished trial replayed on the simulated robot", () => {
  let sim: Simulator;
  let stopRuntime = () => {};
  let closeDb = async () => {};
  let open: (userId: string) => Promise<TrialSocket>;
  let db: ReturnType<typeof createDatabase>["db"];
  let trialId = "";
  let people: Record<"wizard" | "observer", string>;
  let live: Heard[] = [];
  let logBefore = "";

  /** The trial's log and row as stored: what a replay must leave exactly as it was. */
  const stored = async () =>
    JSON.stringify([
      await db.select().from(trialEvents).where(eq(trialEvents.trialId, trialId)).orderBy(asc(trialEvents.seq)),
      await db.select().from(trials).where(eq(trials.id, trialId)),
    ]);

  /** Replays as the observer; resolves with what the robot received once the replay has ended. */
  async function replay(fromMs: number, speed: number) {
    const mark = sim.received.length;
    let socket = await open(people.observer);
    socket.send({ type: "replay", requestId: "r", fromMs, speed });
    let answer = await socket.next((m) => m.requestId === "r");
    // The robot is busy until the trial (or the replay) before has let it go, a moment after it ended: asked again then.
    for (let i = 0; i < 100 && answer.type === "rejected" && /when it is free/.test(JSON.stringify(answer)); i++) {
      socket.close();
      await new Promise((r) => setTimeout(r, 100));
      socket = await open(people.observer);
      socket.send({ type: "replay", requestId: "r", fromMs, speed });
      answer = await socket.next((m) => m.requestId === "r");
    }
    expect(answer).toMatchObject({ type: "ack" });
    const ended = await socket.next((m) => m.type === "replay" && m.playing === false, 20_000);
    socket.close();
    return { heard: heardSince(sim, mark), ended, socket, mark };
  }

  beforeAll(async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { msPerChar: 0 }) });
    const url = await freshDatabaseUrl();
    ({ db, close: closeDb } = createDatabase(url, { max: 4 }));
    const [study] = await db.insert(studies).values({ title: "Replay study", status: "active" }).returning();
    people = { wizard: "", observer: "" };
    for (const who of ["wizard", "observer"] as const) {
      people[who] = (
        await createAccount(db, {
          name: `The ${who}`,
          email: `${who}@replay.example.org`,
          password: "password-123",
          role: "researcher",
        })
      ).id;
      await db.insert(studyMembers).values({ studyId: study!.id, userId: people[who], role: who });
    }
    const [experiment] = await db
      .insert(experiments)
      .values({ studyId: study!.id, name: "Replayed", robotId: "nao6-ros2" })
      .returning();
    const [version] = await db
      .insert(experimentVersions)
      .values({ experimentId: experiment!.id, version: 1, snapshot: protocol, hash: "replay", robotId: "nao6-ros2" })
      .returning();
    const [trial] = await db
      .insert(trials)
      .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id, wizardId: people.wizard })
      .returning();
    trialId = trial!.id;
    // The simulated robot as npm start registers it: the live trial and its replays both take it.
    await db
      .insert(robots)
      .values({ name: "Simulated robot 1", simulated: true, rosbridgeUrl: sim.url, allStudies: true });
    const runtime = await startRuntime(url, SECRET);
    stopRuntime = () => runtime.child.kill("SIGKILL");
    open = (userId) => connectTrial(runtime.url, signSocketToken({ userId, trialId }, SECRET));

    // The live trial: the wizard presses N with uneven pauses until it completes.
    const mark = sim.received.length;
    const wizard = await open(people.wizard);
    expect(await wizard.command("start", { kind: "start" })).toMatchObject({ type: "ack" });
    for (const [i, pause] of PAUSES_MS.entries()) {
      expect(await wizard.command(`n${i}`, { kind: "next" })).toMatchObject({ type: "ack" });
      await new Promise((r) => setTimeout(r, pause));
    }
    await wizard.next((m) => JSON.stringify(m).includes('"trial.completed"'));
    wizard.close();
    // The last message may still be on its way when the log says the trial completed.
    for (let i = 0; i < 100 && heardSince(sim, mark).length < 5; i++) await new Promise((r) => setTimeout(r, 20));
    live = heardSince(sim, mark);
    logBefore = await stored();
  }, 60_000);
  afterAll(async () => {
    stopRuntime();
    await closeDb();
    await sim?.close();
  });

  it("ran the live trial: five messages on the robot's topics, the two of one parallel group together", () => {
    expect(content(live)).toEqual([
      { topic: "/speech", msg: { data: "Hello, I am NAO." } },
      { topic: "/animation", msg: { data: "animations/Stand/Gestures/Hey_1" } },
      { topic: "/speech", msg: { data: "Look at this!" } },
      { topic: "/joint_angles", msg: expect.objectContaining({ joint_names: ["HeadPitch"] }) },
      { topic: "/speech", msg: { data: "Goodbye." } },
    ]);
  });

  it("at ×1: the same messages, in the same order, with the same gaps (±50 ms)", async () => {
    const { heard, ended } = await replay(0, 1);
    expect(content(heard)).toEqual(content(live));
    gaps(heard).forEach((gap, i) => expect(Math.abs(gap - gaps(live)[i]!)).toBeLessThanOrEqual(TOLERANCE_MS));
    expect(ended).toMatchObject({
      playing: false,
      sent: 5,
      total: 5,
      detail: "The replay reached the end of the trial.",
    });
  });

  it("at ×2: the same messages, every gap halved (±50 ms)", async () => {
    const { heard } = await replay(0, 2);
    expect(content(heard)).toEqual(content(live));
    gaps(heard).forEach((gap, i) => expect(Math.abs(gap - gaps(live)[i]! / 2)).toBeLessThanOrEqual(TOLERANCE_MS));
  });

  it("from a moment of the trial: what came before is left out, the rest keeps its gaps", async () => {
    const events = await db
      .select()
      .from(trialEvents)
      .where(eq(trialEvents.trialId, trialId))
      .orderBy(asc(trialEvents.seq));
    // Just before the fourth message (the head looking down) was dispatched.
    const down = events.find((e) => e.type === "action.dispatched" && e.actionId === "down")!;
    const { heard } = await replay(down.relMs! - 1, 1);
    expect(content(heard)).toEqual(content(live.slice(3)));
    expect(Math.abs(gaps(heard)[0]! - gaps(live)[3]!)).toBeLessThanOrEqual(TOLERANCE_MS);
  });

  it("tells the robot page it is a replay, and of which trial, while it plays and when it ends", async () => {
    const { mark } = await replay(0, 2);
    const announced = sim.received
      .slice(mark)
      .filter((r) => r.message.op === "publish" && r.message.topic === REPLAY_TOPIC)
      .map((r) => JSON.parse((r.message.msg as { data: string }).data) as Record<string, unknown>);
    expect(announced[0]).toMatchObject({ trialId, playing: true, speed: 2, total: 5 });
    expect(announced.at(-1)).toMatchObject({ trialId, playing: false, sent: 5 });
  });

  it("stops when asked, sending nothing more", async () => {
    const mark = sim.received.length;
    const socket = await open(people.observer);
    socket.send({ type: "replay", requestId: "r", fromMs: 0, speed: 1 });
    await socket.next((m) => m.type === "replay" && m.sent === 1);
    socket.send({ type: "replay_stop", requestId: "s" });
    expect(await socket.next((m) => m.requestId === "s")).toMatchObject({ type: "ack" });
    expect(await socket.next((m) => m.type === "replay" && m.playing === false)).toMatchObject({
      detail: "Replay stopped.",
    });
    await new Promise((r) => setTimeout(r, 1500));
    expect(content(heardSince(sim, mark))).toEqual(content(live.slice(0, 1)));
    socket.close();
  });

  it("after a quick run of seeks plays only the last, and stops when the page closes", async () => {
    const socket = await open(people.observer);
    for (const id of ["a", "b", "c"]) socket.send({ type: "replay", requestId: id, fromMs: 0, speed: 1 });
    for (const id of ["a", "b", "c"])
      expect(await socket.next((m) => m.requestId === id)).toMatchObject({ type: "ack" });
    // The first two were replaced: each said so before the next began.
    expect(socket.messages.filter((m) => m.type === "replay" && m.detail === "Replay stopped.")).toHaveLength(2);
    socket.close();
    await new Promise((r) => setTimeout(r, 300));
    const mark = sim.received.length;
    // Longer than the whole trial: a replay left playing would have sent the rest by now.
    await new Promise((r) => setTimeout(r, 3000));
    expect(heardSince(sim, mark)).toEqual([]);
  });

  it("stops a replay as soon as its viewer may no longer read the trial's analysis", async () => {
    const socket = await open(people.observer);
    socket.send({ type: "replay", requestId: "r", fromMs: 0, speed: 1 });
    await socket.next((m) => m.type === "replay" && m.sent === 1);
    await db.update(studyMembers).set({ role: "wizard" }).where(eq(studyMembers.userId, people.observer));
    try {
      expect(await socket.next((m) => m.type === "replay" && m.playing === false)).toMatchObject({
        detail: "Replay stopped.",
      });
    } finally {
      await db.update(studyMembers).set({ role: "observer" }).where(eq(studyMembers.userId, people.observer));
      socket.close();
    }
  });

  it("is refused to whoever may not read the trial's analysis (its wizard), with why", async () => {
    const socket = await open(people.wizard);
    socket.send({ type: "replay", requestId: "w", fromMs: 0, speed: 1 });
    expect(await socket.next((m) => m.requestId === "w")).toEqual({
      type: "rejected",
      requestId: "w",
      reason: "As a wizard of this study you may not do this.",
    });
    socket.close();
  });

  it("refuses a speed it does not offer, saying which there are", async () => {
    const socket = await open(people.observer);
    socket.send({ type: "replay", requestId: "x", fromMs: 0, speed: 3 });
    expect(await socket.next((m) => m.requestId === "x")).toMatchObject({
      type: "rejected",
      reason: "A replay plays at ×0.5, ×1, ×2, not ×3.",
    });
    socket.close();
  });

  it("wrote nothing to the trial: its events and row are byte for byte as before", async () => {
    expect(await stored()).toBe(logBefore);
  });
});
