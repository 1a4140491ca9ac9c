// The trial socket's trust boundary (issue 12), over real sockets against a
// real runtime process and PostgreSQL: tokens work once, one hello per
// connection, access changes reach open sockets at once, the welcome carries
// only what the caller may read, and a wizard runs only their own trials.
import { and, eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { participants, studies, studyMembers, trialEvents, trials, user } from "../../src/store/schema";
import { SOCKET_MESSAGES_VERSION } from "../../src/core/socket/messages";
import { socketFixture } from "../support/socket-fixture";
import { connectTrial, type TrialSocket } from "../support/socket";

type Fixture = Awaited<ReturnType<typeof socketFixture>>;
const seqsIn = (socket: TrialSocket) =>
  socket.messages.flatMap((m) => (m.type === "events" ? (m.events as Array<{ seq: number }>).map((e) => e.seq) : []));
const welcomeOf = (socket: TrialSocket) => socket.messages.find((m) => m.type === "welcome")!;
/** A bounded wait for something that must happen soon (never a timing assertion). */
async function eventually(check: () => boolean, what: string, seconds = 3) {
  for (let i = 0; i < seconds * 20 && !check(); i++) await new Promise((r) => setTimeout(r, 50));
  expect(check(), what).toBe(true);
}

describe.sequential("the trial socket's access", () => {
  let f: Fixture;
  beforeAll(async () => {
    f = await socketFixture();
  });
  afterAll(async () => f?.stop());

  it("accepts each token once: the same token cannot say hello again", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const token = f.token(f.a.people.wizard!, trialId);
    const first = await connectTrial(f.url, token);
    expect(welcomeOf(first)).toMatchObject({ trialId, role: "wizard", mayRun: true });
    first.close();
    const again = await connectTrial(f.url, token);
    expect(again.closed).toEqual({ code: 4401, reason: "This link to the trial was already used. Reload the page." });
    expect(again.messages).toEqual([]);
  });

  it("refuses a second hello on a connection, which then receives every event once", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "scheduled");
    const otherStudysTrial = await f.b.trial(f.b.people.wizard!, "live");
    const observer = await f.open("observer", trialId);
    for (let i = 0; i < 5; i++) {
      observer.send({
        type: "hello",
        version: SOCKET_MESSAGES_VERSION,
        token: f.token(f.a.people.observer!, trialId),
        lastSeq: 0,
      });
    }
    // Not even a valid token for another study's trial changes what this connection follows.
    observer.send({
      type: "hello",
      version: SOCKET_MESSAGES_VERSION,
      token: f.token(f.b.people.owner!, otherStudysTrial),
      lastSeq: 0,
    });
    await eventually(() => observer.messages.filter((m) => m.type === "rejected").length === 6, "six hellos refused");
    expect(observer.messages.filter((m) => m.type === "rejected").map((m) => m.reason)).toEqual(
      Array(6).fill("This connection has already said hello: open a new connection to follow another trial."),
    );
    const wizard = await f.open("wizard", trialId);
    expect(await wizard.command("s", { kind: "start" })).toMatchObject({ type: "ack", seqs: [1, 2] });
    expect(await wizard.command("n", { kind: "note", text: "Participant sat down" })).toMatchObject({
      type: "ack",
      seqs: [3],
    });
    await observer.next((m) => m.type === "events" && seqsIn({ ...observer, messages: [m] }).includes(3));
    await wizard.command("n2", { kind: "note", text: "One more, so any duplicate of 3 has arrived" });
    await observer.next((m) => m.type === "events" && seqsIn({ ...observer, messages: [m] }).includes(4));
    expect(seqsIn(observer)).toEqual([1, 2, 3, 4]);
    expect(observer.messages.filter((m) => m.type === "welcome")).toHaveLength(1);
    observer.close();
    wizard.close();
  });

  it("takes what a page sends right behind its hello, before the welcome, once the hello is done, in order", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const notes = ["Sat down", "Looked at the robot", "Smiled"];
    const wizard = await connectTrial(
      f.url,
      f.token(f.a.people.wizard!, trialId),
      0,
      notes.map((text, i) => ({ type: "command", requestId: `early-${i}`, command: { kind: "note", text } })),
    );
    const answers = await Promise.all(
      notes.map((_, i) =>
        wizard.next((m) => m.requestId === `early-${i}` && (m.type === "ack" || m.type === "rejected")),
      ),
    );
    expect(answers.map((a) => a.type)).toEqual(["ack", "ack", "ack"]);
    // After the welcome, and in the order sent.
    expect(wizard.messages.findIndex((m) => m.type === "welcome")).toBeLessThan(
      wizard.messages.findIndex((m) => m.requestId === "early-0"),
    );
    const logged = await f.db
      .select({ payload: trialEvents.payload })
      .from(trialEvents)
      .where(and(eq(trialEvents.trialId, trialId), eq(trialEvents.type, "note.added")))
      .orderBy(trialEvents.seq);
    expect(logged.map((e) => (e.payload as { text: string }).text)).toEqual(notes);
    wizard.close();
  });

  it("cuts off a removed member at once, and refuses them a new connection", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const researcher = await f.open("researcher", trialId);
    expect(welcomeOf(researcher)).toMatchObject({ role: "researcher", mayRun: true });
    await f.db
      .delete(studyMembers)
      .where(and(eq(studyMembers.studyId, f.a.studyId), eq(studyMembers.userId, f.a.people.researcher!)));
    await eventually(() => researcher.closed !== null, "the removed member's socket is closed within a bounded wait");
    expect(researcher.closed).toEqual({ code: 4403, reason: "You are no longer a member of this study." });
    const back = await f.open("researcher", trialId);
    expect(back.closed).toEqual({ code: 4403, reason: "You are no longer a member of this study." });
    await f.db
      .insert(studyMembers)
      .values({ studyId: f.a.studyId, userId: f.a.people.researcher!, role: "researcher" });
  });

  it("cuts off a disabled account at once", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const observer = await f.open("observer", trialId);
    await f.db.update(user).set({ disabled: true }).where(eq(user.id, f.a.people.observer!));
    await eventually(() => observer.closed !== null, "the disabled account's socket is closed");
    expect(observer.closed).toEqual({ code: 4403, reason: "Your account is no longer active." });
    await f.db.update(user).set({ disabled: false }).where(eq(user.id, f.a.people.observer!));
  });

  it("applies a role change to the next command on the open socket, and says so", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const researcher = await f.open("researcher", trialId);
    expect(await researcher.command("r1", { kind: "note", text: "Still a researcher" })).toMatchObject({ type: "ack" });
    await f.db
      .update(studyMembers)
      .set({ role: "observer" })
      .where(and(eq(studyMembers.studyId, f.a.studyId), eq(studyMembers.userId, f.a.people.researcher!)));
    expect(await researcher.next((m) => m.type === "access")).toEqual({
      type: "access",
      role: "observer",
      mayRun: false,
    });
    expect(await researcher.command("r2", { kind: "next" })).toMatchObject({
      type: "rejected",
      reason: "As observer you may watch this trial but not run it.",
    });
    expect(await researcher.command("r3", { kind: "emergency_stop" })).toMatchObject({ type: "rejected" });
    await f.db
      .update(studyMembers)
      .set({ role: "researcher" })
      .where(and(eq(studyMembers.studyId, f.a.studyId), eq(studyMembers.userId, f.a.people.researcher!)));
    expect(await researcher.next((m) => m.type === "access" && m.role === "researcher")).toMatchObject({
      mayRun: true,
    });
    researcher.close();
  });

  it("sends a results-blinded researcher no events of a finished trial, live or later", async () => {
    const finished = await f.a.trial(f.a.people.wizard!, "completed");
    const live = await f.a.trial(f.a.people.wizard!, "live");
    const unblinded = await f.open("researcher", finished);
    expect((welcomeOf(unblinded).events as unknown[]).length).toBe(3);
    unblinded.close();
    await f.db
      .update(studies)
      .set({ settings: { blinding: { conditionsFromWizards: false, resultsUntilComplete: true } } })
      .where(eq(studies.id, f.a.studyId));
    const blinded = await f.open("researcher", finished);
    expect(welcomeOf(blinded)).toMatchObject({ role: "researcher", events: [] });
    const observer = await f.open("observer", finished);
    expect(welcomeOf(observer)).toMatchObject({ events: [] });
    // A wizard never reads results; the owner always may.
    expect(welcomeOf(await f.open("wizard", finished))).toMatchObject({ events: [] });
    expect((welcomeOf(await f.open("owner", finished)).events as unknown[]).length).toBe(3);
    // Watching a live trial unfold is what the socket is for, blind or not.
    const watching = await f.open("researcher", live);
    expect((welcomeOf(watching).events as unknown[]).length).toBe(2);
    await f.db.update(studies).set({ settings: {} }).where(eq(studies.id, f.a.studyId));
    for (const s of [blinded, observer, watching]) s.close();
  });

  it("lets a wizard watch, but not command, another wizard's trial (an emergency stop excepted)", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const other = await f.open("otherWizard", trialId);
    expect(welcomeOf(other)).toMatchObject({ role: "wizard", mayRun: false });
    expect((welcomeOf(other).events as unknown[]).length).toBe(2);
    for (const command of [
      { kind: "next" },
      { kind: "jump", stepId: "A-step-2" },
      { kind: "abort", reason: "mine now" },
      { kind: "note", text: "x" },
    ]) {
      expect(await other.command(`o-${command.kind}`, command)).toMatchObject({
        type: "rejected",
        reason: "This trial is assigned to another wizard: you may watch it but not run it.",
      });
    }
    expect(await other.command("stop", { kind: "emergency_stop" })).toMatchObject({ type: "ack" });
    other.close();
  });

  it("gives an unassigned trial to the first wizard who starts it", async () => {
    const trialId = await f.a.trial(null, "scheduled");
    const first = await f.open("otherWizard", trialId);
    const second = await f.open("wizard", trialId);
    expect(welcomeOf(second)).toMatchObject({ mayRun: true });
    expect(await first.command("s", { kind: "start" })).toMatchObject({ type: "ack" });
    const [row] = await f.db.select({ wizardId: trials.wizardId }).from(trials).where(eq(trials.id, trialId));
    expect(row!.wizardId).toBe(f.a.people.otherWizard);
    expect(await second.next((m) => m.type === "access")).toEqual({ type: "access", role: "wizard", mayRun: false });
    expect(await second.command("n", { kind: "next" })).toMatchObject({
      type: "rejected",
      reason: "This trial is assigned to another wizard: you may watch it but not run it.",
    });
    expect(await first.command("n", { kind: "next" })).toMatchObject({ type: "ack" });
    first.close();
    second.close();
  });

  it("records the researcher who starts an unassigned trial as its wizard, its creator kept apart", async () => {
    const trialId = await f.a.trial(null, "scheduled");
    await f.db.update(trials).set({ createdBy: f.a.people.owner }).where(eq(trials.id, trialId));
    const researcher = await f.open("researcher", trialId);
    const wizard = await f.open("wizard", trialId);
    expect(await researcher.command("s", { kind: "start" })).toMatchObject({ type: "ack" });
    const [row] = await f.db
      .select({ wizardId: trials.wizardId, createdBy: trials.createdBy })
      .from(trials)
      .where(eq(trials.id, trialId));
    expect(row).toEqual({ wizardId: f.a.people.researcher, createdBy: f.a.people.owner });
    expect(await wizard.next((m) => m.type === "access")).toEqual({ type: "access", role: "wizard", mayRun: false });
    researcher.close();
    wizard.close();
  });

  it("starts no trial of a study set back to draft, and starts it once the study is active again", async () => {
    const trialId = await f.a.trial(null, "scheduled");
    await f.db.update(studies).set({ status: "draft" }).where(eq(studies.id, f.a.studyId));
    try {
      const early = await f.open("researcher", trialId);
      expect(await early.command("s", { kind: "start" })).toMatchObject({
        type: "rejected",
        reason: expect.stringMatching(/^This study is still a draft: rehearse its experiments from the designer/),
      });
      early.close();
      const [row] = await f.db.select({ wizardId: trials.wizardId }).from(trials).where(eq(trials.id, trialId));
      expect(row!.wizardId).toBeNull();
    } finally {
      await f.db.update(studies).set({ status: "active" }).where(eq(studies.id, f.a.studyId));
    }
    const later = await f.open("researcher", trialId);
    expect(await later.command("s", { kind: "start" })).toMatchObject({ type: "ack" });
    later.close();
  });

  it("logs a recording only on its own trial", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const mine = await f.recording(trialId);
    const elsewhere = await f.recording(await f.a.trial(f.a.people.wizard!, "live"));
    const wizard = await f.open("wizard", trialId);
    expect(await wizard.command("other", { kind: "recording", recordingId: elsewhere, offsetMs: 0 })).toMatchObject({
      type: "rejected",
      reason: "That recording belongs to another trial: it was not logged here.",
    });
    expect(await wizard.command("mine", { kind: "recording", recordingId: mine, offsetMs: 0 })).toMatchObject({
      type: "ack",
    });
    wizard.close();
  });

  it("replays only a finished trial, only for whoever may read its analysis, and says when there is no simulated robot", async () => {
    const finished = await f.a.trial(f.a.people.wizard!, "completed");
    const live = await f.a.trial(f.a.people.wizard!, "live");
    const replay = async (who: "observer" | "wizard" | "owner", trialId: string) => {
      const socket = await f.open(who, trialId);
      socket.send({ type: "replay", requestId: "r", fromMs: 0, speed: 1 });
      const reply = await socket.next((m) => m.requestId === "r");
      socket.close();
      return reply.reason;
    };
    // This runtime, like one driving a real robot, has no simulated robot to replay on.
    expect(await replay("observer", finished)).toBe(
      "Replay needs the simulated robot; this server has none running (it drives a real robot, and a replay never moves one).",
    );
    expect(await replay("wizard", finished)).toBe("As a wizard of this study you may not do this.");
    expect(await replay("owner", live)).toBe("Only a finished trial can be replayed: this one has not ended yet.");
    // A withdrawn participant's trial is no more replayed than it is analysed.
    const [withdrawn] = await f.db
      .insert(participants)
      .values({ studyId: f.a.studyId, code: "P-GONE", consentStatus: "withdrawn" })
      .returning();
    await f.db.update(trials).set({ participantId: withdrawn!.id }).where(eq(trials.id, finished));
    expect(await replay("observer", finished)).toBe(
      "P-GONE withdrew from the study: their data is excluded from analysis and exports.",
    );
    const events = await f.db.select().from(trialEvents).where(eq(trialEvents.trialId, finished));
    expect(events.map((e) => e.type)).toEqual(["trial.started", "step.entered", "trial.completed"]);
  });

  it("refuses someone who is not a member of the trial's study at hello", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const outsider = await f.open("outsider", trialId);
    expect(outsider.closed).toEqual({ code: 4403, reason: "You are no longer a member of this study." });
    expect(outsider.messages).toEqual([]);
  });
});
