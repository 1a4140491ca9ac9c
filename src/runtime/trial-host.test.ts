import { afterAll, describe, expect, it } from "vitest";
import { bareTrial, bareWizard, freshDatabase } from "../../tests/support/db";
import { answeredRequests, eventsSince, takeTrial } from "@/store/event-store";
import type { StoredEvent, TrialProtocol } from "@/core/trial";
import { groupWriter } from "./log-writer";
import type { RobotLink, RobotReport } from "./robot";
import { TrialHost } from "./trial-host";

const protocol: TrialProtocol = {
  steps: [
    {
      id: "s1",
      name: "One",
      actions: [
        { id: "hold", type: "pause", parameters: { seconds: 0.05 } },
        { id: "hi", type: "say", parameters: { text: "hi" } },
      ],
    },
  ],
};

/** A robot that answers every action at once: the host's own logic under test, not a transport. */
function timekeeperRobot(): RobotLink {
  return {
    perform(request, report) {
      report({ kind: "dispatched", actionId: request.actionId });
      setTimeout(() => report({ kind: "completed", actionId: request.actionId }), 0);
    },
    halt() {},
    connected: () => true,
    onConnection() {},
    onProblem() {},
    watchState: () => () => {},
    watchCamera: () => () => {},
    watchSenses: () => () => {},
    close() {},
  };
}

describe("a live trial host", async () => {
  const { db, close } = await freshDatabase();
  afterAll(close);

  const newTrialId = () => bareTrial(db);

  const settle = (host: TrialHost, predicate: () => boolean) =>
    new Promise<void>((resolve) => {
      const check = () => predicate() && resolve();
      host.subscribe(check);
      check();
    });

  it("commits, then tells subscribers, and carries out pauses and robot actions", async () => {
    const trialId = await newTrialId();
    const host = await TrialHost.open(db, trialId, protocol, timekeeperRobot());
    const seen: number[] = [];
    host.subscribe((events) => seen.push(...events.map((e) => e.seq)));
    expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
    await host.command({ kind: "next" }, null);
    await settle(host, () => host.current.actions.hold!.status === "done");
    await host.command({ kind: "next" }, null);
    await settle(host, () => host.current.actions.hi!.status === "done");
    const log = await eventsSince(db, trialId);
    expect(log.map((e) => e.type)).toEqual([
      "trial.started",
      "step.entered",
      "action.requested",
      "action.dispatched",
      "action.completed",
      "action.requested",
      "action.dispatched",
      "action.completed",
    ]);
    expect(seen).toEqual(log.map((e) => e.seq));
    const held = log[4]!.relMs! - log[2]!.relMs!;
    expect(held).toBeGreaterThanOrEqual(50);
    await host.close();
  });

  it("refuses what the engine refuses, writing nothing", async () => {
    const trialId = await newTrialId();
    const host = await TrialHost.open(db, trialId, protocol, timekeeperRobot());
    expect(await host.command({ kind: "next" }, null)).toEqual({ ok: false, reason: "The trial is not running." });
    expect(await eventsSince(db, trialId)).toEqual([]);
    await host.close();
  });

  it("rebuilds from its events after a restart and marks the interrupted action sent, outcome unknown", async () => {
    const trialId = await newTrialId();
    const never = { ...timekeeperRobot(), perform() {} };
    const first = await TrialHost.open(db, trialId, protocol, never);
    await first.command({ kind: "start" }, null);
    await first.command({ kind: "skip", actionId: "hold" }, null);
    await first.command({ kind: "next" }, null);
    // The process dies here: no close, the robot never answered.
    const second = await TrialHost.open(db, trialId, protocol, timekeeperRobot());
    expect(second.current.actions.hi!.status).toBe("unknown");
    expect(second.current.currentStepId).toBe("s1");
    const log = await eventsSince(db, trialId);
    expect(log.at(-1)).toMatchObject({
      type: "action.unknown",
      reason: expect.stringMatching(/^The trial runtime restarted while this action was under way: it may have/),
    });
    expect(log.map((e) => e.seq)).toEqual([1, 2, 3, 4, 5]);
    await second.close();
  });

  it("gives the log it opened with, and what it appended since, to one hello only: after the seq asked for", async () => {
    const trialId = await newTrialId();
    const first = await TrialHost.open(db, trialId, protocol, timekeeperRobot());
    await first.command({ kind: "start" }, null);
    await first.close();
    const opened = () => TrialHost.open(db, trialId, protocol, timekeeperRobot());
    const whole = await opened();
    await whole.command({ kind: "skip", actionId: "hold" }, null);
    const all = await eventsSince(db, trialId);
    expect(whole.takeOpeningLog(0)).toEqual(all);
    expect(whole.takeOpeningLog(0)).toBeNull();
    await whole.close();
    const after = await opened();
    expect(after.takeOpeningLog(2)).toEqual(all.filter((e) => e.seq > 2));
    await after.close();
  });

  /** The log's append (src/store/event-store.ts appendMany), not the host's other reads through the same client. */
  const isAppend = (first: unknown) =>
    Array.isArray(first) && "raw" in first && first.join("").includes("insert into trial_events");

  it("recovers when a commit's reply is lost: the events are taken as landed, never written twice", async () => {
    const trialId = await newTrialId();
    // The database as it is, except that the first append commits and then loses its reply, as a
    // connection dropped between COMMIT and its answer would.
    const real = db.$client;
    let lose = true;
    const lossy = ((first: unknown, ...rest: unknown[]) => {
      if (!isAppend(first) || !lose) return (real as (...a: unknown[]) => unknown)(first, ...rest);
      lose = false;
      return Promise.resolve((real as (...a: unknown[]) => unknown)(first, ...rest)).then(() => {
        throw Object.assign(new Error("write CONNECTION_CLOSED"), { code: "CONNECTION_CLOSED" });
      });
    }) as typeof real;
    const flaky = Object.assign(Object.create(db) as typeof db, { $client: lossy });
    const host = await TrialHost.open(flaky, trialId, protocol, timekeeperRobot());
    expect(await host.command({ kind: "start" }, null)).toEqual({ ok: true, seqs: [1, 2] });
    expect(lose).toBe(false);
    expect((await host.command({ kind: "next" }, null)).ok).toBe(true);
    const log = await eventsSince(db, trialId);
    expect(log.map((e) => e.seq)).toEqual(log.map((_, i) => i + 1));
    expect(log.filter((e) => e.type === "trial.started")).toHaveLength(1);
    await host.close();
  });

  /** The database as it is, except that `wrap` decides what the next append (only that one) does. */
  const withNextAppend = (wrap: (append: () => Promise<unknown>) => Promise<unknown>) => {
    const real = db.$client;
    let armed = false;
    const client = ((first: unknown, ...rest: unknown[]) => {
      const call = () => (real as (...a: unknown[]) => unknown)(first, ...rest);
      if (!isAppend(first) || !armed) return call();
      armed = false;
      return wrap(() => Promise.resolve(call()));
    }) as typeof real;
    return { db: Object.assign(Object.create(db) as typeof db, { $client: client }), arm: () => (armed = true) };
  };
  const recordingRobot = () => {
    const performed: string[] = [];
    return {
      performed,
      robot: { ...timekeeperRobot(), perform: (r: { actionId: string }) => performed.push(r.actionId) },
    };
  };
  const say = (actionId: string) =>
    ({ kind: "unscripted", actionId, actionType: "say", parameters: { text: actionId } }) as const;

  it("answers the wizard by the log's deadline though the write has not returned, and never sends what lands after it", async () => {
    const trialId = await newTrialId();
    const slow = withNextAppend((append) => new Promise((r) => setTimeout(r, 3600)).then(append));
    const { performed, robot } = recordingRobot();
    const host = await TrialHost.open(slow.db, trialId, protocol, robot);
    expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
    slow.arm();
    const answer = await host.command(say("slow-line"), null);
    expect(answer).toMatchObject({ ok: false, reason: expect.stringMatching(/^The trial log did not answer in time/) });
    // The write lands after the answer: in the log as asked for, then not sent.
    await settle(host, () => host.current.actions["slow-line"]?.status === "not_sent");
    const log = await eventsSince(db, trialId);
    expect(log.slice(-2)).toMatchObject([
      { type: "action.requested", actionId: "slow-line" },
      {
        type: "action.not_sent",
        actionId: "slow-line",
        reason: expect.stringMatching(/^Not sent: the trial log answered too late/),
      },
    ]);
    expect(performed).toEqual([]);
    await host.close();
  });

  it("takes in a write it was told had failed that lands later, refuses the command that meets it, and never sends it", async () => {
    const trialId = await newTrialId();
    // Refused at once, committed a moment later: as a statement sent just before its connection broke.
    const ghost = withNextAppend((append) => {
      setTimeout(() => void append(), 100);
      return Promise.reject(Object.assign(new Error("write CONNECTION_CLOSED"), { code: "CONNECTION_CLOSED" }));
    });
    const { performed, robot } = recordingRobot();
    const host = await TrialHost.open(ghost.db, trialId, protocol, robot);
    expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
    ghost.arm();
    await expect(host.command(say("ghost-line"), null)).rejects.toThrow("CONNECTION_CLOSED");
    await expect.poll(async () => (await eventsSince(db, trialId)).length).toBe(3);
    expect(await host.command({ kind: "note", text: "after" }, null)).toEqual({
      ok: false,
      reason: expect.stringMatching(/^Not carried out: an earlier command reached the trial log late/),
    });
    await settle(host, () => host.current.actions["ghost-line"]?.status === "not_sent");
    const log = await eventsSince(db, trialId);
    expect(log.map((e) => e.seq)).toEqual(log.map((_, i) => i + 1));
    expect(log.slice(2)).toMatchObject([
      { type: "action.requested", actionId: "ghost-line" },
      { type: "action.not_sent", actionId: "ghost-line", reason: expect.stringMatching(/^Not sent/) },
    ]);
    expect(log.some((e) => e.type === "note.added")).toBe(false);
    expect(performed).toEqual([]);
    // The host carries on from the log as it is.
    expect(await host.command({ kind: "note", text: "after" }, null)).toMatchObject({ ok: true });
    await host.close();
  });

  it("refuses a line logged as its lock was lost, before the new owner came: the robot is not told, the log says so", async () => {
    const trialId = await newTrialId();
    let owned = true;
    const ownership = { epoch: (await takeTrial(db, trialId))!, lost() {}, owns: async () => owned };
    const { performed, robot } = recordingRobot();
    const host = await TrialHost.open(db, trialId, protocol, robot, undefined, ownership);
    expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
    // The lock is found lost (another process took it) while the append, still under the host's epoch, goes in.
    owned = false;
    expect(await host.command(say("unsaid"), null)).toEqual({
      ok: false,
      reason: expect.stringMatching(
        /^Not carried out: another runtime process took this trial over as this was logged/,
      ),
    });
    await settle(host, () => host.current.actions.unsaid?.status === "not_sent");
    expect((await eventsSince(db, trialId)).slice(2)).toMatchObject([
      { type: "action.requested", actionId: "unsaid" },
      { type: "action.not_sent", actionId: "unsaid", reason: expect.stringMatching(/^Not sent: another runtime/) },
    ]);
    expect(performed).toEqual([]);
    // What the robot is not asked to do is carried out as before.
    expect(await host.command({ kind: "note", text: "still logged" }, null)).toMatchObject({ ok: true });
    await host.close();
  });

  /** The transaction that wrote each of the trial's events, by seq: events of one commit share it. */
  const transactions = async (trialId: string) =>
    (
      await db.$client<Array<{ xmin: string }>>`
      select xmin::text from trial_events where trial_id = ${trialId} order by seq`
    ).map((r) => r.xmin);

  it("writes an action's outcomes that happen together in one append: a completion with the dispatch", async () => {
    const trialId = await newTrialId();
    const atOnce: RobotLink = {
      ...timekeeperRobot(),
      perform(request, report) {
        report({ kind: "dispatched", actionId: request.actionId });
        report({ kind: "completed", actionId: request.actionId });
      },
    };
    const host = await TrialHost.open(db, trialId, protocol, atOnce);
    await host.command({ kind: "start" }, null);
    await host.command(say("at-once"), null);
    await settle(host, () => host.current.actions["at-once"]?.status === "done");
    const log = await eventsSince(db, trialId);
    expect(log.slice(2).map((e) => [e.seq, e.type])).toEqual([
      [3, "action.requested"],
      [4, "action.dispatched"],
      [5, "action.completed"],
    ]);
    const [, , requested, dispatched, completed] = await transactions(trialId);
    expect(completed).toBe(dispatched);
    // Requested is committed before the robot is told: never in the same commit as what the robot did.
    expect(requested).not.toBe(dispatched);
    await host.close();
  });

  it("joins a report that comes while its action's last one waits behind another trial's commit", async () => {
    const [trialId, otherId] = [await newTrialId(), await newTrialId()];
    let release = () => {};
    const held = withNextAppend((append) => new Promise<void>((r) => (release = r)).then(append));
    const log = groupWriter(held.db);
    let tell: (report: RobotReport) => void = () => {};
    const robot: RobotLink = { ...timekeeperRobot(), perform: (_, report) => (tell = report) };
    const host = await TrialHost.open(held.db, trialId, protocol, robot, log);
    const other = await TrialHost.open(held.db, otherId, protocol, timekeeperRobot(), log);
    await host.command({ kind: "start" }, null);
    await host.command(say("later"), null);
    // Another trial's commit is under way (held): what this trial's robot reports meanwhile waits for the next.
    held.arm();
    const note = other.command({ kind: "note", text: "meanwhile" }, null);
    tell({ kind: "dispatched", actionId: "later" });
    // A moment apart (not a measure of anything): the dispatch is waiting for its commit when the completion comes.
    await new Promise((r) => setTimeout(r, 20));
    tell({ kind: "completed", actionId: "later" });
    release();
    expect(await note).toMatchObject({ ok: true, seqs: [1] });
    await settle(host, () => host.current.actions.later?.status === "done");
    expect((await eventsSince(db, trialId)).map((e) => [e.seq, e.type])).toEqual([
      [1, "trial.started"],
      [2, "step.entered"],
      [3, "action.requested"],
      [4, "action.dispatched"],
      [5, "action.completed"],
    ]);
    const [, , , dispatched, completed] = await transactions(trialId);
    expect(completed).toBe(dispatched);
    expect((await transactions(otherId))[0]).not.toBe(dispatched);
    await host.close();
    await other.close();
  });

  const actionOf = (event: StoredEvent) => ("actionId" in event ? event.actionId : null);

  /** A robot that reports only when the test tells it to, on the last action it was asked to perform. */
  const toldRobot = () => {
    const robot = { tell: (_report: RobotReport) => {} };
    const link: RobotLink = { ...timekeeperRobot(), perform: (_, report) => void (robot.tell = report) };
    return { robot, link };
  };

  /**
   * A trial started on a told robot by a wizard going back to back (so the robot's reports wait for the next
   * command), its line "one" logged and sent: the robot has reported nothing yet.
   */
  const oneLineSaid = async (database = db) => {
    const [trialId, wizard] = [await newTrialId(), await bareWizard(db)];
    const { robot, link } = toldRobot();
    const host = await TrialHost.open(database, trialId, protocol, link);
    // The line asked for before the start is answered: back to back, whatever the machine's pace.
    await Promise.all([host.command({ kind: "start" }, wizard), host.command(say("one"), wizard)]);
    return { trialId, wizard, robot, host };
  };

  it("carries the robot's reports that wait in the next command's append: the next line and the last one's outcomes, one commit", async () => {
    const { trialId, wizard, robot, host } = await oneLineSaid();
    robot.tell({ kind: "dispatched", actionId: "one" });
    robot.tell({ kind: "completed", actionId: "one" });
    // The wizard's next line, straight after: the answer names its own events only.
    expect(await host.command(say("two"), wizard, { id: "request-two" })).toEqual({ ok: true, seqs: [6] });
    // The reports are the robot's, by no one and answering no request, as in an append of their own.
    expect((await eventsSince(db, trialId)).slice(2).map((e) => [e.seq, e.type, actionOf(e), e.actorId])).toEqual([
      [3, "action.requested", "one", wizard],
      [4, "action.dispatched", "one", null],
      [5, "action.completed", "one", null],
      [6, "action.requested", "two", wizard],
    ]);
    expect(await answeredRequests(db, trialId)).toEqual(new Map([["request-two", [6]]]));
    const [, , requested, dispatched, completed, next] = await transactions(trialId);
    expect([completed, next]).toEqual([dispatched, dispatched]);
    expect(requested).not.toBe(dispatched);
    expect(host.current.actions.one?.status).toBe("done");
    await host.close();
  });

  it("logs the robot's reports at once for a wizard at a human pace: in their own commit, as they came", async () => {
    const { trialId, wizard, robot, host } = await oneLineSaid();
    // A moment to think, as a person takes (longer than BACK_TO_BACK_MS; not a measure of anything).
    await new Promise((r) => setTimeout(r, 150));
    await host.command(say("two"), wizard);
    robot.tell({ kind: "dispatched", actionId: "two" });
    expect(await host.command({ kind: "note", text: "right after" }, wizard)).toMatchObject({ ok: true });
    expect((await eventsSince(db, trialId)).slice(3).map((e) => [e.seq, e.type])).toEqual([
      [4, "action.requested"],
      [5, "action.dispatched"],
      [6, "note.added"],
    ]);
    const [, , , requested, dispatched, note] = await transactions(trialId);
    expect(new Set([requested, dispatched, note]).size).toBe(3);
    await host.close();
  });

  it("logs at once a report long after the last answer (a line's end), though the wizard went back to back", async () => {
    const { trialId, wizard, robot, host } = await oneLineSaid();
    // Longer than BACK_TO_BACK_MS after the last answer: such a wizard would have sent the next command by now.
    await new Promise((r) => setTimeout(r, 150));
    robot.tell({ kind: "dispatched", actionId: "one" });
    expect(await host.command({ kind: "note", text: "right after" }, wizard)).toMatchObject({ ok: true });
    const [, , , dispatched, note] = await transactions(trialId);
    expect(dispatched).not.toBe(note);
    await host.close();
  });

  it("leaves the reports waiting when the command is refused: they go in an append of their own", async () => {
    const { trialId, robot, host } = await oneLineSaid();
    robot.tell({ kind: "dispatched", actionId: "one" });
    expect(await host.command({ kind: "jump", stepId: "s1" }, null)).toEqual({
      ok: false,
      reason: "The trial is already at that step.",
    });
    await settle(host, () => host.current.actions.one?.status === "running");
    expect((await eventsSince(db, trialId)).slice(2).map((e) => [e.type, actionOf(e)])).toEqual([
      ["action.requested", "one"],
      ["action.dispatched", "one"],
    ]);
    await host.close();
  });

  it("logs the robot's reports that wait as the host closes: they came while it ran the trial", async () => {
    const { trialId, robot, host } = await oneLineSaid();
    robot.tell({ kind: "dispatched", actionId: "one" });
    await host.close();
    // After the close: not from here.
    robot.tell({ kind: "completed", actionId: "one" });
    await new Promise((r) => setTimeout(r, 20));
    expect((await eventsSince(db, trialId)).slice(2).map((e) => [e.type, actionOf(e)])).toEqual([
      ["action.requested", "one"],
      ["action.dispatched", "one"],
    ]);
  });

  it("writes the reports a command carried that met an earlier write landed late: the log holds them", async () => {
    // Refused at once, committed a moment later: as a statement sent just before its connection broke.
    const ghost = withNextAppend((append) => {
      setTimeout(() => void append(), 100);
      return Promise.reject(Object.assign(new Error("write CONNECTION_CLOSED"), { code: "CONNECTION_CLOSED" }));
    });
    const { trialId, wizard, robot, host } = await oneLineSaid(ghost.db);
    ghost.arm();
    await expect(host.command(say("ghost-line"), null)).rejects.toThrow("CONNECTION_CLOSED");
    await expect.poll(async () => (await eventsSince(db, trialId)).length).toBe(4);
    // Two commands at once (refused, logging nothing): the wizard back to back again, so the report waits for the note.
    const jump = { kind: "jump", stepId: "s1" } as const;
    await Promise.all([host.command(jump, wizard), host.command(jump, wizard)]);
    robot.tell({ kind: "dispatched", actionId: "one" });
    expect(await host.command({ kind: "note", text: "after" }, null)).toEqual({
      ok: false,
      reason: expect.stringMatching(/^Not carried out: an earlier command reached the trial log late/),
    });
    await settle(host, () => host.current.actions["ghost-line"]?.status === "not_sent");
    expect((await eventsSince(db, trialId)).slice(2).map((e) => [e.seq, e.type, actionOf(e)])).toEqual([
      [3, "action.requested", "one"],
      [4, "action.requested", "ghost-line"],
      [5, "action.dispatched", "one"],
      [6, "action.not_sent", "ghost-line"],
    ]);
    await host.close();
  });

  it("carries out a request once, answering the same id again with its first outcome, after a restart too", async () => {
    const trialId = await newTrialId();
    const first = await TrialHost.open(db, trialId, protocol, timekeeperRobot());
    expect(await first.command({ kind: "start" }, null, { id: "start-1" })).toEqual({ ok: true, seqs: [1, 2] });
    const note = { kind: "note", text: "once" } as const;
    const answer = await first.command(note, null, { id: "note-1" });
    expect(answer).toEqual({ ok: true, seqs: [3] });
    // Sent again on the same connection, and as a retry after a reconnect: the same answer, nothing written.
    expect(await first.command(note, null, { id: "note-1" })).toEqual(answer);
    expect(await first.command(note, null, { id: "note-1", retry: true })).toEqual(answer);
    // A refusal is an outcome too.
    const refused = await first.command({ kind: "jump", stepId: "nowhere" }, null, { id: "jump-1" });
    expect(refused.ok).toBe(false);
    expect(await first.command({ kind: "jump", stepId: "nowhere" }, null, { id: "jump-1" })).toEqual(refused);
    // The runtime restarts: the log still knows the request.
    const second = await TrialHost.open(db, trialId, protocol, timekeeperRobot());
    expect(await second.command(note, null, { id: "note-1", retry: true })).toEqual(answer);
    // A retry of a request the trial never received is not carried out now, late.
    expect(await second.command(note, null, { id: "note-2", retry: true })).toEqual({
      ok: false,
      reason: "Not carried out: the connection dropped before this reached the trial. Ask again if you still want it.",
    });
    const notes = (await eventsSince(db, trialId)).filter((e) => e.type === "note.added");
    expect(notes).toHaveLength(1);
    await first.close();
    await second.close();
  });
});
