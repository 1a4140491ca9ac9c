// Results by condition on a real database: two conditions, each its own
// experiment, finished trials in both (the wizard's run from the engine,
// stored through the event store, 1 s between events), SUS answers through
// the participant's one-time link; the figures and the tidy CSV compared with
// the numbers worked out by hand. A rehearsal and a withdrawn participant
// count nowhere, and a results blind refuses both.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { type Command, type EngineEvent, simulate, type TrialProtocol } from "../../src/core/trial";
import { appendEvents, type TrialCursor } from "../../src/store/event-store";
import { buildFixture } from "../api/fixture";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

const STEPS = [
  {
    name: "Greeting",
    actions: [{ type: "say", parameters: { text: "Hello!" } }, { type: "wave" }, { type: "nod" }],
  },
  { name: "Goodbye", actions: [{ type: "end_trial" }] },
];
/** Every positive (odd) item at `v`, every negative one at 1: a SUS of (5v + 15) × 2.5. */
const SUS = (v: number) => Object.fromEntries(Array.from({ length: 10 }, (_, i) => [`sus${i + 1}`, i % 2 ? 1 : v]));

/** The gestures named skipped up front, then next until the end, the robot finishing each action it is sent. */
function wizardRun(protocol: TrialProtocol, skip: string[]): EngineEvent[] {
  const commands: Command[] = [];
  const send = (command: Command) => {
    const { last } = simulate(protocol, [...commands, command]);
    expect(last, JSON.stringify(command)).not.toBeTypeOf("string");
    commands.push(command);
    return last as EngineEvent[];
  };
  send({ kind: "start" });
  for (const a of protocol.steps[0]!.actions) if (skip.includes(a.type)) send({ kind: "skip", actionId: a.id });
  for (let i = 0; i < 20; i++) {
    const last = send({ kind: "next" });
    for (const e of last)
      if (e.type === "action.requested" && e.actionType !== "end_trial") {
        send({ kind: "dispatched", actionId: e.actionId });
        send({ kind: "completed", actionId: e.actionId });
      }
    if (last.some((e) => e.type === "trial.completed"))
      return simulate(protocol, commands).log.map(({ seq: _seq, relMs: _relMs, ...event }) => event as EngineEvent);
  }
  throw new Error("The trial did not end after 20 × next.");
}

async function store(trialId: string, events: EngineEvent[]) {
  const start = Date.parse("2026-11-23T10:00:00Z");
  const cursor: TrialCursor = { id: trialId, lastSeq: 0, t0: null };
  for (const [i, event] of events.entries()) {
    const at = new Date(start + i * 1000);
    await appendEvents(db, cursor, [event], f.people.owner.id, { now: () => at });
    cursor.lastSeq++;
    cursor.t0 ??= at;
  }
}

let studyId = "";
beforeAll(async () => {
  const study = await f.newStudy();
  studyId = study.id;
  const sus = await owner.questionnaires.create({ studyId, instrument: "sus" });
  await owner.questionnaires.publish({ questionnaireId: sus.id });
  const arm = async (name: string) => {
    const experiment = await owner.experiments.create({ studyId, name, robotId: "nao6-ros2" });
    await owner.experiments.saveDesign({ experimentId: experiment.id, baseRevision: 0, steps: STEPS });
    const version = await owner.versions.publish({ experimentId: experiment.id });
    const condition = await owner.conditions.create({ studyId, name, experimentId: experiment.id });
    return { experiment, version, condition };
  };
  const gestures = await arm("Gestures");
  const still = await arm("Still");
  const run = async (trialId: string, skip: string[]) =>
    store(trialId, wizardRun((await owner.trials.get({ trialId })).protocol as TrialProtocol, skip));
  await run((await owner.trials.rehearse({ experimentId: gestures.experiment.id })).id, ["wave", "nod"]);
  // [code, arm, gestures skipped, SUS answer (positive items), withdraws]
  const people: Array<[string, typeof gestures, string[], number | null, boolean]> = [
    ["P1", gestures, [], 4, false],
    ["P2", gestures, ["wave"], 5, false],
    ["P3", gestures, [], 3, false],
    ["P4", still, ["wave", "nod"], 2, false],
    ["P5", still, ["wave", "nod"], null, false],
    ["P7", still, [], 5, true],
  ];
  for (const [code, { version, condition }, skip, answer, withdraws] of people) {
    const p = await owner.participants.create({ studyId, code, consentStatus: "given", consentDate: new Date() });
    await owner.conditions.assign({ participantId: p.id, conditionId: condition.id });
    const trial = await owner.trials.create({ versionId: version.id, participantId: p.id });
    await run(trial.id, skip);
    if (answer !== null) {
      const { token } = await owner.questionnaires.createLink({ questionnaireId: sus.id, participantId: p.id });
      await f.api("anonymous").form.submit({ token, answers: SUS(answer) });
    }
    if (withdraws) await owner.participants.update({ participantId: p.id, consentStatus: "withdrawn" });
  }
});

describe("results by condition", () => {
  it("describes each measure per condition", async () => {
    const r = await owner.studies.resultsByCondition({ studyId });
    expect(r.conditions).toEqual([
      { condition: "Gestures", trials: 3 },
      { condition: "Still", trials: 2 },
    ]);
    const of = (measure: string) =>
      Object.fromEntries(r.measures.find((m) => m.measure === measure)!.byCondition.map((c) => [c.condition, c.stats]));
    // All four scripted actions (say, wave, nod, end) count: a skipped gesture is a quarter of them.
    // 100, 75, 100: deviations from the mean of 8⅓, 16⅔, 8⅓, so SD = √((2 × 69.4 + 277.8) / 2) = 25 / √3.
    expect(of("Execution fidelity")).toEqual({
      Gestures: { n: 3, mean: 275 / 3, sd: expect.closeTo(25 / Math.sqrt(3), 9), median: 100, min: 75, max: 100 },
      Still: { n: 2, mean: 50, sd: 0, median: 50, min: 50, max: 50 },
    });
    expect(of("Deviations per trial")).toMatchObject({
      Gestures: { n: 3, mean: 1 / 3, median: 0, min: 0, max: 1 },
      Still: { n: 2, mean: 2, sd: 0 },
    });
    // 87.5, 100 and 75; 62.5 alone (P5 did not answer, withdrawn P7's answer is left out).
    expect(of("Questionnaire score: System Usability Scale (SUS)")).toEqual({
      Gestures: { n: 3, mean: 87.5, sd: 12.5, median: 87.5, min: 75, max: 100 },
      Still: { n: 1, mean: 62.5, sd: null, median: 62.5, min: 62.5, max: 62.5 },
    });
    // Stored 1 s apart: a full greeting takes 10 s, and each skipped gesture saves two events (dispatched,
    // completed: the skip replaces the request), so 8 s with one skipped and 6 s with two.
    expect(of("Time in step: Greeting")).toEqual({
      Gestures: {
        n: 3,
        mean: 28000 / 3,
        sd: expect.closeTo(2000 / Math.sqrt(3), 9),
        median: 10000,
        min: 8000,
        max: 10000,
      },
      Still: { n: 2, mean: 6000, sd: 0, median: 6000, min: 6000, max: 6000 },
    });
    // The whole trial: the greeting and 3 s more for the goodbye.
    expect(of("Trial duration")).toMatchObject({
      Gestures: { median: 13000, min: 11000, max: 13000 },
      Still: { median: 9000, min: 9000, max: 9000 },
    });
  });

  it("downloads the tidy CSV: one row per condition and measure", async () => {
    const { body, filename, contentType } = await owner.studies.resultsByConditionCsv({ studyId });
    expect([filename, contentType]).toEqual(["results-by-condition.csv", "text/csv; charset=utf-8"]);
    const [header, ...rows] = parseCsv(body);
    expect(header).toEqual(["condition", "measure", "n", "mean", "sd", "median", "min", "max"]);
    expect(rows.map((row) => `${row[0]} · ${row[1]} · n=${row[2]}`)).toEqual([
      "Gestures · Execution fidelity (%) · n=3",
      "Still · Execution fidelity (%) · n=2",
      "Gestures · Deviations per trial · n=3",
      "Still · Deviations per trial · n=2",
      "Gestures · Trial duration (ms) · n=3",
      "Still · Trial duration (ms) · n=2",
      "Gestures · Time in step: Greeting (ms) · n=3",
      "Still · Time in step: Greeting (ms) · n=2",
      "Gestures · Time in step: Goodbye (ms) · n=3",
      "Still · Time in step: Goodbye (ms) · n=2",
      "Gestures · Questionnaire score: System Usability Scale (SUS) · n=3",
      "Still · Questionnaire score: System Usability Scale (SUS) · n=1",
    ]);
    expect(rows[1]!.slice(3)).toEqual(["50", "0", "50", "50", "50"]);
  });

  it("is refused to a researcher while the study hides results", async () => {
    await owner.studies.update({ studyId, settings: { blinding: { resultsUntilComplete: true } } });
    const researcher = f.api("researcher");
    await expect(researcher.studies.resultsByCondition({ studyId })).rejects.toMatchObject({ code: "FORBIDDEN" });
    await expect(researcher.studies.resultsByConditionCsv({ studyId })).rejects.toMatchObject({ code: "FORBIDDEN" });
    await owner.studies.update({ studyId, settings: { blinding: { resultsUntilComplete: false } } });
  });
});
