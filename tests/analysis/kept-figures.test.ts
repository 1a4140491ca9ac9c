// The Results tab keeps each ended trial's figures (trial_figures) so it need
// not fold every log again. On a real database, through the real procedures:
// what is kept is what the pure functions compute from the log, the tables
// built from kept copies equal those built from the logs, a copy is read while
// it stands and folded again when it does not (a robot's late report, another
// figures version, another protocol version), and who counts is still decided
// at each read: live trials and rehearsals are not kept, a withdrawn
// participant's trial leaves the tables, and a results blind still refuses.
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { resultsByCondition } from "../../src/core/analysis/by-condition";
import { fidelityReport } from "../../src/core/analysis/fidelity";
import { studySummary } from "../../src/core/analysis/study-summary";
import { FIGURES_VERSION, reportFigures } from "../../src/core/analysis/trial-figures";
import { type Command, simulate, type TrialEvent, type TrialProtocol } from "../../src/core/trial";
import { appendEvents, eventsSince, type TrialCursor } from "../../src/store/event-store";
import { trialFigures } from "../../src/store/schema";
import { buildFixture, publishedVersion } from "../api/fixture";
import { freshDatabase } from "../support/db";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

/** A trial as the runtime writes it: each command's events through the event store, 1 s after the last. */
function trialWriter(trialId: string, protocol: TrialProtocol) {
  const commands: Command[] = [];
  const cursor: TrialCursor = { id: trialId, lastSeq: 0, t0: null };
  let at = Date.parse("2026-11-24T10:00:00Z");
  return async (...sent: Command[]) => {
    for (const command of sent) {
      const { last } = simulate(protocol, [...commands, command]);
      if (typeof last === "string") throw new Error(`${command.kind}: ${last}`);
      commands.push(command);
      const now = new Date((at += 1000));
      await appendEvents(db, cursor, last, f.people.owner.id, { now: () => now });
      cursor.lastSeq += last.length;
      cursor.t0 ??= now;
    }
  };
}

let studyId = "";
let protocol: TrialProtocol;
const trialOf: Record<string, string> = {};
/** The wave still running when P2's trial is completed: the robot's report of it comes after the end. */
let lateWave: ReturnType<typeof trialWriter>;
let waveId = "";

beforeAll(async () => {
  studyId = (await f.newStudy()).id;
  const { experiment, version } = await publishedVersion(owner, studyId);
  protocol = version.snapshot as TrialProtocol;
  waveId = protocol.steps[0]!.actions[0]!.id;
  const condition = await owner.conditions.create({ studyId, name: "Waving", experimentId: experiment.id });
  const trial = async (code: string) => {
    const p = await owner.participants.create({ studyId, code, consentStatus: "given", consentDate: new Date() });
    await owner.conditions.assign({ participantId: p.id, conditionId: condition.id });
    trialOf[code] = (await owner.trials.create({ versionId: version.id, participantId: p.id })).id;
    return trialWriter(trialOf[code], protocol);
  };
  const done: Command[] = [
    { kind: "dispatched", actionId: waveId },
    { kind: "completed", actionId: waveId },
  ];
  await (await trial("P1"))({ kind: "start" }, { kind: "next" }, ...done, { kind: "complete" });
  lateWave = await trial("P2");
  await lateWave({ kind: "start" }, { kind: "next" }, done[0]!, { kind: "complete" });
  await (await trial("P3"))(
    { kind: "start" },
    { kind: "unscripted", actionId: "extra", actionType: "nod", parameters: {} },
    { kind: "skip", actionId: waveId },
    { kind: "abort", reason: "ill" },
  );
  await (await trial("P4"))({ kind: "start" });
  const rehearsal = (await owner.trials.rehearse({ experimentId: experiment.id })).id;
  trialOf.rehearsal = rehearsal;
  await trialWriter(rehearsal, (await owner.trials.get({ trialId: rehearsal })).protocol as TrialProtocol)(
    { kind: "start" },
    { kind: "complete" },
  );
});

const kept = async () => Object.fromEntries((await db.select().from(trialFigures)).map((r) => [r.trialId, r]));
/** The trial's figures folded from its log now, with nothing kept. */
const computed = async (code: string) =>
  reportFigures(fidelityReport(protocol, (await eventsSince(db, trialOf[code]!)) as unknown as TrialEvent[]));
const figuresOf = async () =>
  Object.fromEntries((await owner.studies.figures({ studyId })).trials.map((t) => [t.participantCode, t]));
const setKept = (code: string, change: Record<string, unknown>) =>
  db.update(trialFigures).set(change).where(eq(trialFigures.trialId, trialOf[code]!));

describe("the figures kept for the Results tab", () => {
  it("keeps each ended trial's figures as the pure functions compute them, and nothing of live trials or rehearsals", async () => {
    await owner.studies.figures({ studyId });
    const rows = await kept();
    expect(Object.keys(rows).sort()).toEqual([trialOf.P1, trialOf.P2, trialOf.P3].sort());
    for (const code of ["P1", "P2", "P3"]) {
      const events = await eventsSince(db, trialOf[code]!);
      expect(rows[trialOf[code]!]).toMatchObject({
        figuresVersion: FIGURES_VERSION,
        lastSeq: events.at(-1)!.seq,
        figures: await computed(code),
      });
    }
  });

  it("gives the tables the logs give, whether the figures are kept or folded", async () => {
    const reports = await Promise.all(
      ["P1", "P2", "P3"].map(async (code) => ({
        trialId: trialOf[code]!,
        participantCode: code,
        condition: "Waving",
        report: fidelityReport(protocol, (await eventsSince(db, trialOf[code]!)) as unknown as TrialEvent[]),
      })),
    );
    const fromKept = await owner.studies.figures({ studyId });
    expect(fromKept).toEqual(studySummary(reports));
    expect(fromKept.trials.map((t) => [t.participantCode, t.executionFidelity])).toEqual([
      ["P1", 100],
      ["P2", 0],
      ["P3", 0],
    ]);
    expect(await owner.studies.resultsByCondition({ studyId })).toEqual(resultsByCondition(reports, []));
    // The deviation kinds in the order the trials met them, as the tab lists them (not sorted by the database).
    expect(Object.keys(fromKept.consistency.deviationsByKind)).toEqual(["unscripted", "skipped"]);
    await db.delete(trialFigures);
    // Both at once, as the Results tab asks for them: one fold of each log, shared, and the same tables.
    const [folded, byCondition] = await Promise.all([
      owner.studies.figures({ studyId }),
      owner.studies.resultsByCondition({ studyId }),
    ]);
    expect(folded).toEqual(fromKept);
    expect(byCondition).toEqual(resultsByCondition(reports, []));
    expect(Object.keys(await kept())).toHaveLength(3);
  });

  it("reads a kept copy while it stands, without folding the log again", async () => {
    const { figures } = (await kept())[trialOf.P1!]!;
    await setKept("P1", { figures: { ...(figures as object), executionFidelity: 42 } });
    expect((await figuresOf()).P1!.executionFidelity).toBe(42);
    await setKept("P1", { figures });
  });

  it.each<[string, (row: typeof trialFigures.$inferSelect) => Record<string, unknown>]>([
    ["kept under another figures version", () => ({ figuresVersion: FIGURES_VERSION - 1 })],
    ["kept for another protocol version", () => ({ versionId: "another-version" })],
    ["folded from fewer events than the log holds", (row) => ({ lastSeq: row.lastSeq - 1 })],
  ])("folds the log again when the copy was %s", async (_, stale) => {
    const row = (await kept())[trialOf.P1!]!;
    await setKept("P1", { ...stale(row), figures: { ...(row.figures as object), executionFidelity: 42 } });
    expect((await figuresOf()).P1!.executionFidelity).toBe(100);
    expect((await kept())[trialOf.P1!]).toMatchObject({
      figuresVersion: FIGURES_VERSION,
      versionId: row.versionId,
      lastSeq: row.lastSeq,
      figures: await computed("P1"),
    });
  });

  it("folds again when the robot reports after the end: the late completion counts", async () => {
    expect((await figuresOf()).P2!.executionFidelity).toBe(0);
    await lateWave({ kind: "completed", actionId: waveId });
    expect((await figuresOf()).P2!.executionFidelity).toBe(100);
    const events = await eventsSince(db, trialOf.P2!);
    expect((await kept())[trialOf.P2!]).toMatchObject({ lastSeq: events.at(-1)!.seq, figures: await computed("P2") });
  });

  it("is still refused to a researcher while the study hides results", async () => {
    await owner.studies.update({ studyId, settings: { blinding: { resultsUntilComplete: true } } });
    const researcher = f.api("researcher");
    await expect(researcher.studies.figures({ studyId })).rejects.toMatchObject({ code: "FORBIDDEN" });
    await expect(researcher.studies.resultsByCondition({ studyId })).rejects.toMatchObject({ code: "FORBIDDEN" });
    await owner.studies.update({ studyId, settings: { blinding: { resultsUntilComplete: false } } });
    expect((await researcher.studies.figures({ studyId })).trials).toHaveLength(3);
  });

  it("leaves a participant who withdrew out, though their figures were kept", async () => {
    const p2 = (await owner.participants.list({ studyId })).find((p) => p.code === "P2")!;
    expect((await kept())[trialOf.P2!]).toBeDefined();
    await owner.participants.update({ participantId: p2.id, consentStatus: "withdrawn" });
    expect(Object.keys(await figuresOf())).toEqual(["P1", "P3"]);
    expect((await owner.studies.resultsByCondition({ studyId })).conditions).toEqual([
      { condition: "Waving", trials: 2 },
    ]);
  });
});
