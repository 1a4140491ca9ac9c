// The study's methods text of a seeded two-condition study, checked fact by
// fact against the database: every number a sentence states is counted here
// again from the rows it comes from (participants, trials and their events,
// robots, versions, responses), or read from the screen that shows it (the
// Coding tab's kappa, the Results tab's fidelity).
import { strFromU8 } from "fflate";
import { sql } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import packageJson from "../../package.json";
import type { EngineEvent } from "../../src/core/trial";
import { readSnapshot } from "../../src/core/protocol/snapshot";
import { appendEvents } from "../../src/store/event-store";
import { experimentVersions, participants, robots, trials } from "../../src/store/schema";
import { eq } from "drizzle-orm";
import { freshDatabase } from "../support/db";
import { studyRowCounts } from "../support/study-rows";
import { buildFixture, unzipArchive } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

const study = await f.newStudy("Storytelling and memory");
await owner.studies.update({
  studyId: study.id,
  settings: { assignment: { strategy: "balanced", perCondition: 1 }, blinding: { conditionsFromWizards: true } },
});
const say = (text: string) => ({ type: "say", parameters: { text } });
async function published(
  name: string,
  story: Array<{ type: string; parameters?: Record<string, unknown> }>,
  storyLimit?: { seconds: number; after: { to: "next" } },
) {
  const experiment = await owner.experiments.create({ studyId: study.id, name, robotId: "nao6-ros2" });
  await owner.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [
      { name: "Greeting", actions: [say("Hello, I am NAO.")] },
      { name: "Story", actions: story, ...(storyLimit ? { timeLimit: storyLimit } : {}) },
      { name: "Goodbye", actions: [say("Goodbye!")] },
    ],
  });
  const version = await owner.versions.publish({ experimentId: experiment.id });
  const [row] = await db.select().from(experimentVersions).where(eq(experimentVersions.id, version.id));
  return { experiment, version: row!, snapshot: readSnapshot(row!.snapshot) };
}
const gestures = await published("Story with gestures", [say("Once upon a time…"), { type: "wave" }]);
// The still story may last 20 s: its time limit is a line only its condition has.
const still = await published("Story standing still", [say("Once upon a time…")], {
  seconds: 20,
  after: { to: "next" },
});
const withGestures = await owner.conditions.create({
  studyId: study.id,
  name: "With gestures",
  experimentId: gestures.experiment.id,
});
const standingStill = await owner.conditions.create({
  studyId: study.id,
  name: "Standing still",
  experimentId: still.experiment.id,
});
// The trials ran on the lab's robots, not on the NAO6 the experiments were designed for.
const [simulator, nao] = await db
  .insert(robots)
  .values([
    { name: "Lab simulator", simulated: true },
    { name: "Lab NAO", simulated: false },
  ])
  .returning();

type Run = "perfect" | "skips the wave" | "stopped in the story";
const T0 = Date.parse("2026-03-02T10:00:00Z");

/** A trial as the runtime writes it, on a clock of our own: each step lasts the given ms. */
async function ran(
  code: string,
  consentStatus: "given" | "declined" | "withdrawn",
  condition: { id: string },
  run: { robotId: string; durations: number[]; how: Run } | null,
) {
  const arm = condition === withGestures ? gestures : still;
  const [participant] = await db
    .insert(participants)
    .values({ studyId: study.id, code, consentStatus, conditionId: condition.id })
    .returning();
  if (!run) return;
  const [trial] = await db
    .insert(trials)
    .values({
      studyId: study.id,
      experimentId: arm.experiment.id,
      versionId: arm.version.id,
      participantId: participant!.id,
      assignedRobotId: run.robotId,
    })
    .returning();
  let cursor = { id: trial!.id, lastSeq: 0, t0: null as Date | null };
  let at = 0;
  const append = async (events: EngineEvent[]) => {
    const now = new Date(T0 + at);
    await appendEvents(db, cursor, events, f.people.wizard.id, { now: () => now });
    cursor = { ...cursor, lastSeq: cursor.lastSeq + events.length, t0: cursor.t0 ?? now };
  };
  await append([{ type: "trial.started" }]);
  for (const [i, step] of arm.snapshot.steps.entries()) {
    await append([{ type: "step.entered", stepId: step.id, via: i ? "next" : "start" }]);
    for (const action of step.actions) {
      if (run.how === "skips the wave" && action.type === "wave") {
        await append([{ type: "action.skipped", stepId: step.id, actionId: action.id, deviation: "skipped" }]);
        continue;
      }
      const request = {
        type: "action.requested" as const,
        stepId: step.id,
        actionId: action.id,
        actionType: action.type,
        parameters: action.parameters,
        scripted: true,
      };
      await append([request, { type: "action.completed", actionId: action.id }]);
    }
    at += run.durations[i]!;
    if (run.how === "stopped in the story" && step.name === "Story") {
      await append([{ type: "trial.aborted", reason: "The participant had to leave" }]);
      return;
    }
  }
  await append([{ type: "trial.completed" }]);
}

await ran("P01", "given", withGestures, { robotId: simulator!.id, durations: [3000, 10_000, 2000], how: "perfect" });
await ran("P02", "given", withGestures, {
  robotId: simulator!.id,
  durations: [5000, 12_000, 2000],
  how: "skips the wave",
});
await ran("P05", "withdrawn", withGestures, { robotId: nao!.id, durations: [9000, 9000, 9000], how: "perfect" });
await ran("P07", "given", withGestures, {
  robotId: simulator!.id,
  durations: [4000, 1500],
  how: "stopped in the story",
});
await ran("P03", "given", standingStill, { robotId: nao!.id, durations: [2000, 8000, 1000], how: "perfect" });
await ran("P04", "given", standingStill, { robotId: nao!.id, durations: [2500, 9000, 1500], how: "perfect" });
await ran("P06", "declined", standingStill, null);

// A questionnaire after the trial, answered by one participant.
const sus = await owner.questionnaires.create({ studyId: study.id, instrument: "sus" });
await owner.questionnaires.save({ questionnaireId: sus.id, timing: "after" });
await owner.questionnaires.publish({ questionnaireId: sus.id });
const [p01] = await db.select().from(participants).where(eq(participants.code, "P01"));
const link = await owner.questionnaires.createLink({ questionnaireId: sus.id, participantId: p01!.id });
await f
  .api("anonymous")
  .form.submit({ token: link.token, answers: Object.fromEntries([...Array(10)].map((_, i) => [`sus${i + 1}`, 4])) });

// Two observers code the wizard's interventions in P01's trial.
const [firstTrial] = await db.select().from(trials).where(eq(trials.participantId, p01!.id));
const scheme = await owner.coding.createScheme({ studyId: study.id, template: "wizard-interventions" });
const schemeVersion = await owner.coding.publishScheme({ codingSchemeId: scheme.id });
const code = (who: "owner" | "observer", codeId: string, startMs: number) =>
  f.api(who).coding.addCode({
    trialId: firstTrial!.id,
    schemeVersionId: schemeVersion.id,
    setId: "intervention",
    codeId,
    startMs,
  });
await code("owner", "hint", 1500);
await code("owner", "technical", 6500);
await code("observer", "hint", 1700);
await code("observer", "guidance", 9200);

const methods = await owner.studies.methods({ studyId: study.id });
const text = methods.text;
const count = async (query: ReturnType<typeof sql>) => Number((await db.execute<{ n: number }>(query))[0]!.n);
const seconds = (ms: number) => (ms / 1000).toFixed(1);

describe("each fact of the methods text is the database's", () => {
  it("the design: between subjects, with the study's conditions", async () => {
    const n = await count(sql`select count(*) as n from conditions where study_id = ${study.id}`);
    expect(n).toBe(2);
    expect(text).toContain(
      `The study had a between-subjects design: each participant took part in one condition. It had ${n} conditions: “Standing still” (experiment “Story standing still”) and “With gestures” (experiment “Story with gestures”).`,
    );
  });

  it.each([
    ["With gestures", () => withGestures.id],
    ["Standing still", () => standingStill.id],
  ])("n per condition, %s: enrolled, completed, withdrawn, excluded with reasons", async (name, id) => {
    const of = (where: ReturnType<typeof sql>) =>
      count(sql`select count(*) as n from participants p where p.condition_id = ${id()} and ${where}`);
    const enrolled = await of(sql`true`);
    const withdrawn = await of(sql`p.consent_status = 'withdrawn'`);
    const finished = (status: string) =>
      sql`exists (select 1 from trials t where t.participant_id = p.id and t.status = ${status})`;
    const completed = await of(sql`p.consent_status <> 'withdrawn' and ${finished("completed")}`);
    const declined = await of(sql`p.consent_status = 'declined'`);
    const stopped = await of(
      sql`p.consent_status not in ('withdrawn', 'declined') and ${finished("aborted")} and not ${finished("completed")}`,
    );
    const reasons = [
      declined ? `${declined} declined consent` : "",
      stopped ? `${stopped} whose trial was stopped before its end` : "",
    ].filter(Boolean);
    expect(reasons.length).toBe(1); // each condition shows one kind of exclusion
    expect(text).toContain(
      `“${name}”: ${enrolled} enrolled, ${completed} completed, ${withdrawn} withdrew; ${declined + stopped} excluded (${reasons[0]}).`,
    );
  });

  it("the assignment and its seed, as the study's settings hold them", async () => {
    const [row] = await db.execute<{ seed: string }>(
      sql`select settings->'assignment'->>'seed' as seed from studies where id = ${study.id}`,
    );
    expect(row!.seed).toBeTruthy();
    expect(text).toContain(`The assignment's seed was ${row!.seed}, from which it can be reproduced.`);
    expect(text).toContain("HRIStudio assigned participants in shuffled blocks holding each condition once");
  });

  it("the blinding the study set", () => {
    expect(text).toContain("Wizards were blind to condition");
    expect(text).toContain("Researchers and observers could see results while the study ran.");
  });

  it("the robots the trials ran on, from the trials' rows, never the experiments' planned robot", async () => {
    const used = await db.execute<{ name: string; simulated: boolean; hash: string; version: string; n: number }>(sql`
      select r.name, r.simulated, v.plugin_hash as hash, v.plugin_version as version, count(*)::int as n
      from trials t join robots r on r.id = t.assigned_robot_id join experiment_versions v on v.id = t.version_id
      join participants p on p.id = t.participant_id
      where t.study_id = ${study.id} and t.t0 is not null and p.consent_status <> 'withdrawn'
      group by 1, 2, 3, 4 order by 1`);
    expect(used.map((r) => r.name)).toEqual(["Lab NAO", "Lab simulator"]);
    for (const r of used) {
      expect(r.hash).toBeTruthy();
      expect(text).toContain(
        `“${r.name}” (${r.simulated ? "simulated" : "physical"}; plugin “NAO6 Robot (ROS2 Integration)”, version ${r.version}, SHA-256 ${r.hash}; ${r.n} trials)`,
      );
    }
  });

  it("each condition's published version, and the steps where the protocols differ", async () => {
    for (const [name, arm] of [
      ["With gestures", gestures],
      ["Standing still", still],
    ] as const)
      expect(text).toContain(
        `“${name}” ran version ${arm.version.version} of “${arm.experiment.name}” (SHA-256 ${arm.version.hash})`,
      );
    const shared = text.slice(text.indexOf("The conditions shared these steps"), text.indexOf("They differed"));
    expect(shared).toContain("1. Greeting. The robot said “Hello, I am NAO.”");
    expect(shared).toContain("3. Goodbye. The robot said “Goodbye!”");
    // Each condition's own lines: from its heading to the next blank line.
    const only = (name: string) => text.slice(text.indexOf(`Only in ${name}\n`)).split("\n\n")[0];
    expect(only("With gestures")).toMatch(
      /^Only in With gestures\n2\. Story\. The robot said “Once upon a time…” Then the robot performed “[^”]+”\.$/,
    );
    // The time limit as the published version holds it, and the step it leads to.
    const [story, goodbye] = still.snapshot.steps.slice(1);
    expect(only("Standing still")).toBe(
      `Only in Standing still\n2. Story. The robot said “Once upon a time…” If the step had not ended within ${story!.timeLimit!.seconds} seconds, the trial went on to “${goodbye!.name}”.`,
    );
  });

  it.each([
    ["With gestures", () => gestures],
    ["Standing still", () => still],
  ])("the step timings of %s, from its trials' logged step entries", async (name, arm) => {
    // The same trials the Results tab folds: finished, not rehearsals, of participants still in.
    const rows = await db.execute<{ trial_id: string; type: string; step_id: string | null; rel_ms: number }>(sql`
      select e.trial_id, e.type, e.step_id, e.rel_ms from trial_events e join trials t on t.id = e.trial_id
      join participants p on p.id = t.participant_id
      where t.experiment_id = ${arm().experiment.id} and t.status in ('completed', 'aborted') and p.consent_status <> 'withdrawn'
        and e.type in ('step.entered', 'trial.completed', 'trial.aborted')
      order by e.trial_id, e.seq`);
    const parts = arm().snapshot.steps.map((step) => {
      const durations = rows.flatMap((r, i) =>
        r.step_id === step.id && r.type === "step.entered" ? [rows[i + 1]!.rel_ms - r.rel_ms] : [],
      );
      const sorted = durations.sort((a, b) => a - b);
      const median =
        sorted.length % 2
          ? sorted[(sorted.length - 1) / 2]!
          : (sorted[sorted.length / 2 - 1]! + sorted[sorted.length / 2]!) / 2;
      const range = sorted[0] !== sorted.at(-1) ? `, range ${seconds(sorted[0]!)}–${seconds(sorted.at(-1)!)} s` : "";
      return `“${step.name}” median ${seconds(median)} s${range} (n = ${sorted.length})`;
    });
    expect(text).toContain(`In “${name}”, measured from the trials' logs: ${parts.join("; ")}.`);
  });

  it("the questionnaire with its item count, its responses and its scoring reference", async () => {
    const responses = await count(sql`
      select count(*) as n from questionnaire_responses r join questionnaire_links l on l.id = r.link_id
      where l.study_id = ${study.id} and r.status = 'submitted'`);
    expect(text).toContain(
      `After the trial: “System Usability Scale (SUS)” (10 items; ${responses} response), scored as published`,
    );
    expect(text).toContain("(Brooke, 1996");
  });

  /** The sentence on the scheme's agreement, from what the Results tab computes as the scheme keeps it. */
  const agreementSentence = async (words: string) => {
    const agreement = await owner.coding.agreement({ schemeVersionId: schemeVersion.id });
    const pooled = agreement.pairs[0]!.pooled[0]!;
    const [a, b] = agreement.pairs
      .map((p) => [p.a, p.b])[0]!
      .map((id) => agreement.observers.find((o) => o.id === id)!.name);
    return {
      n: pooled.n,
      sentence: `Observers coded with “Wizard interventions” (version ${schemeVersion.version}); agreement was counted in ${words}: “Intervention type”: Cohen's κ = ${pooled.kappa!.toFixed(2)} between ${a} and ${b} (${pooled.n} slices).`,
    };
  };

  it("the coding scheme's agreement, as the Results tab computes it, with what it counted", async () => {
    const whole = await agreementSentence("1 s slices, the whole trial");
    expect(text).toContain(whole.sentence);
    // Kept with the scheme, another window is the one the text counts and says.
    const counted = { sliceMs: 1000, window: "bothCoding" as const, stepIds: [] };
    await owner.coding.keepCounted({ codingSchemeId: scheme.id, counted });
    const both = await agreementSentence("1 s slices, from when both observers had coded");
    expect(both.n).toBeLessThan(whole.n);
    expect((await owner.studies.methods({ studyId: study.id })).text).toContain(both.sentence);
    await owner.coding.keepCounted({ codingSchemeId: scheme.id, counted: { ...counted, window: "trial" } });
  });

  it.each([
    ["With gestures", () => gestures],
    ["Standing still", () => still],
  ])("fidelity and deviations of %s, as the Results tab and the logs have them", async (name, arm) => {
    const figures = await owner.studies.figures({ studyId: study.id });
    const rows = figures.trials.filter((t) => t.condition === name);
    const mean = rows.reduce((s, r) => s + r.executionFidelity, 0) / rows.length;
    const skipped = await count(sql`
      select count(*) as n from trial_events e join trials t on t.id = e.trial_id join participants p on p.id = t.participant_id
      where t.experiment_id = ${arm().experiment.id} and p.consent_status <> 'withdrawn' and e.payload->>'deviation' = 'skipped'`);
    const exact = rows.filter((r) => r.deviations === 0).length;
    const deviations = skipped ? `deviations: ${skipped} action skipped` : "no deviations";
    expect(text).toMatch(
      new RegExp(
        `“${name}”: mean execution fidelity ${mean.toFixed(1)}% \\(SD [0-9.]+\\) over ${rows.length} trials; ${exact} of ${rows.length} without any deviation; ${deviations}\\.`,
      ),
    );
  });

  it("the software's version", () => {
    expect(text).toContain(`generated with HRIStudio ${packageJson.version}.`);
  });
});

it("the study's zip holds the same methods text, and reading it wrote nothing", async () => {
  const before = await studyRowCounts(db, study.id);
  const files = await unzipArchive(await f.routeApi("owner").studies.exportArchive({ studyId: study.id }));
  expect(strFromU8(files["methods.md"]!)).toBe((await owner.studies.methods({ studyId: study.id })).markdown);
  expect(await studyRowCounts(db, study.id)).toEqual(before);
});
