// Running a whole study: results hidden until the study is complete,
// withdrawal taking a participant's data out of analysis and exports,
// demographics and the consent document's version, and sessions.
import { eq } from "drizzle-orm";
import { strFromU8 } from "fflate";
import { afterAll, describe, expect, it } from "vitest";
import { auditLog } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture, unzipArchive } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

/** A study with a published experiment, a condition on it, and a consenting participant with a trial. */
async function runningStudy() {
  const study = await f.newStudy();
  const experiment = await owner.experiments.create({ studyId: study.id, name: "Story", robotId: "nao6-ros2" });
  await owner.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "Hello", actions: [{ type: "wave" }] }],
  });
  const version = await owner.versions.publish({ experimentId: experiment.id });
  const condition = await owner.conditions.create({ studyId: study.id, name: "Waving", experimentId: experiment.id });
  const participant = await owner.participants.create({
    studyId: study.id,
    code: "P001",
    consentStatus: "given",
    consentDate: new Date(),
  });
  const trial = await owner.trials.create({ versionId: version.id, participantId: participant.id });
  return { study, experiment, version, condition, participant, trial };
}

const actions = async (studyId: string) =>
  (await db.select({ action: auditLog.action }).from(auditLog).where(eq(auditLog.studyId, studyId))).map(
    (r) => r.action,
  );

describe("results hidden until the study is complete", () => {
  it("refuses researchers and observers the data, lets the owner see it, and logs the lifting", async () => {
    const { study, trial } = await runningStudy();
    await owner.studies.update({
      studyId: study.id,
      settings: { blinding: { conditionsFromWizards: false, resultsUntilComplete: true } },
    });
    for (const caller of ["researcher", "observer"] as const) {
      await expect(f.api(caller).trials.export({ trialId: trial.id, format: "json" })).rejects.toMatchObject({
        code: "FORBIDDEN",
        message: "This study hides results until it is marked completed (blinding).",
      });
      await expect(f.api(caller).trials.events({ trialId: trial.id })).rejects.toMatchObject({ code: "FORBIDDEN" });
    }
    await expect(owner.trials.export({ trialId: trial.id, format: "csv" })).resolves.toMatchObject({
      contentType: expect.stringMatching(/csv/),
    });
    await owner.studies.update({ studyId: study.id, status: "completed" });
    await expect(f.api("researcher").trials.export({ trialId: trial.id, format: "json" })).resolves.toBeTruthy();
    expect(await actions(study.id)).toContain("study.blind.lifted.results");
  });

  it("logs turning off the wizards' blind", async () => {
    const { study } = await runningStudy();
    await owner.studies.update({
      studyId: study.id,
      settings: { blinding: { conditionsFromWizards: true, resultsUntilComplete: false } },
    });
    await expect(f.api("wizard").conditions.list({ studyId: study.id })).rejects.toMatchObject({ code: "FORBIDDEN" });
    expect((await f.api("wizard").participants.list({ studyId: study.id }))[0]!.conditionId).toBeNull();
    await owner.studies.update({
      studyId: study.id,
      settings: { blinding: { conditionsFromWizards: false, resultsUntilComplete: false } },
    });
    expect(await actions(study.id)).toContain("study.blind.lifted.conditions");
    await expect(f.api("wizard").conditions.list({ studyId: study.id })).resolves.toHaveLength(1);
  });
});

describe("study settings", () => {
  it("changes only the settings given: choosing a strategy keeps the blinds and the consent check", async () => {
    const study = await f.newStudy();
    await owner.studies.update({
      studyId: study.id,
      settings: { requireConsent: false, blinding: { conditionsFromWizards: true, resultsUntilComplete: true } },
    });
    await owner.studies.update({
      studyId: study.id,
      settings: { assignment: { strategy: "balanced", perCondition: 2 } },
    });
    expect((await owner.studies.get({ studyId: study.id })).settings).toMatchObject({
      requireConsent: false,
      blinding: { conditionsFromWizards: true, resultsUntilComplete: true },
      assignment: { strategy: "balanced", perCondition: 2, seed: expect.any(String) },
    });
  });
});

describe("lists", () => {
  it("count what they say: steps and versions of experiments, participants per condition, trials per participant", async () => {
    const { study, experiment, condition, participant } = await runningStudy();
    await owner.conditions.assign({ participantId: participant.id, conditionId: condition.id });
    const q = await owner.questionnaires.create({ studyId: study.id, instrument: "sus" });
    await owner.questionnaires.publish({ questionnaireId: q.id });
    expect(await owner.experiments.list({ studyId: study.id })).toMatchObject([
      { id: experiment.id, stepCount: 1, latestVersion: 1 },
    ]);
    expect(await owner.conditions.list({ studyId: study.id })).toMatchObject([{ participantCount: 1 }]);
    expect(await owner.participants.list({ studyId: study.id })).toMatchObject([{ trialCount: 1 }]);
    expect(await owner.questionnaires.list({ studyId: study.id })).toMatchObject([{ latestVersion: 1 }]);
    expect((await owner.studies.mine()).find((s) => s.id === study.id)).toMatchObject({
      experimentCount: 1,
      trialCount: 1,
      participantCount: 1,
    });
  });
});

describe("withdrawal", () => {
  it("takes the participant's data out of analysis and exports, keeps it stored, logs it, and allows no new trial", async () => {
    const { study, version, participant, trial } = await runningStudy();
    await owner.participants.update({ participantId: participant.id, consentStatus: "withdrawn" });
    const refused = {
      code: "PRECONDITION_FAILED",
      message: "P001 withdrew from the study: their data is excluded from analysis and exports.",
    };
    await expect(owner.trials.export({ trialId: trial.id, format: "json" })).rejects.toMatchObject(refused);
    await expect(owner.trials.events({ trialId: trial.id })).rejects.toMatchObject(refused);
    await expect(owner.trials.samples({ trialId: trial.id })).rejects.toMatchObject(refused);
    expect((await owner.trials.list({ studyId: study.id }))[0]).toMatchObject({
      id: trial.id,
      participantWithdrawn: true,
    });
    expect(await actions(study.id)).toContain("participant.consent.withdrawn");
    await owner.studies.update({ studyId: study.id, settings: { requireConsent: false } });
    await expect(owner.trials.create({ versionId: version.id, participantId: participant.id })).rejects.toMatchObject({
      code: "PRECONDITION_FAILED",
      message: expect.stringMatching(/has withdrawn/),
    });
  });
});

describe("the methods text", () => {
  it("describes a published version with the study's robot, conditions, assignment and questionnaires", async () => {
    const { study, version } = await runningStudy();
    await owner.studies.update({ studyId: study.id, settings: { assignment: { strategy: "random" } } });
    const sus = await owner.questionnaires.create({ studyId: study.id, instrument: "sus" });
    await owner.questionnaires.save({ questionnaireId: sus.id, timing: "after" });
    await owner.questionnaires.create({ studyId: study.id, name: "Not attached" });
    const { markdown, text } = await owner.versions.methods({ versionId: version.id });
    for (const fact of [
      "## Methods: Story, version 1",
      "1. **Hello.** The robot performed “Wave”.",
      "After the trial, participants completed “System Usability Scale (SUS)” (10 items).",
      "The study had 1 condition: “Waving” (experiment “Story”).",
      "at random, from a seed stored with the study",
      `The version's SHA-256 hash is \`${version.hash}\`.`,
    ])
      expect(markdown).toContain(fact);
    expect(markdown).not.toContain("Not attached");
    expect(text).toContain(`The version's SHA-256 hash is ${version.hash}.`);
    expect(text).not.toContain("**");
  });
});

describe("the study archive", () => {
  it("holds the design, every trial's record and events, and the answers, without withdrawn participants", async () => {
    const { study, version, trial } = await runningStudy();
    const other = await owner.participants.create({
      studyId: study.id,
      code: "P002",
      consentStatus: "given",
      consentDate: new Date(),
    });
    const withdrawnTrial = await owner.trials.create({ versionId: version.id, participantId: other.id });
    await owner.participants.update({ participantId: other.id, consentStatus: "withdrawn" });
    // A second experiment of the same name: its methods text gets a file of its own.
    const twin = await owner.experiments.create({ studyId: study.id, name: "Story", robotId: "nao6-ros2" });
    await owner.experiments.saveDesign({
      experimentId: twin.id,
      baseRevision: 0,
      steps: [{ name: "Hi", actions: [{ type: "nod" }] }],
    });
    const twinVersion = await owner.versions.publish({ experimentId: twin.id });
    const archive = await f.routeApi("owner").studies.exportArchive({ studyId: study.id });
    expect(archive).toMatchObject({ filename: "fixture-study.zip", contentType: "application/zip" });
    const files = await unzipArchive(archive);
    expect(Object.keys(files).sort()).toEqual([
      "README.txt",
      "codebook.csv",
      "codes.csv",
      expect.stringMatching(/^experiments\/story-v1-[0-9a-f-]{8}-methods\.md$/),
      "experiments/story-v1-methods.md",
      "methods.md",
      "questionnaire-answers.csv",
      "study.json",
      `trials/${trial.id}-events.csv`,
      `trials/${trial.id}-samples.csv`,
      `trials/${trial.id}.eaf`,
      `trials/${trial.id}.json`,
    ]);
    const content = JSON.parse(strFromU8(files["study.json"]!));
    expect(content).toMatchObject({
      participants: [{ code: "P001" }],
      withdrawnParticipants: 1,
      // The experiment and its namesake.
      experiments: [
        { name: "Story", versions: [{ version: 1 }] },
        { name: "Story", versions: [{ version: 1 }] },
      ],
    });
    expect(JSON.stringify(content)).not.toContain("P002");
    // The methods text of each published version, as the designer previews it, and listed in the README.
    const methodsFiles = Object.keys(files)
      .filter((name) => name.startsWith("experiments/"))
      .map((name) => strFromU8(files[name]!))
      .sort();
    expect(methodsFiles).toEqual(
      (await Promise.all([version, twinVersion].map((v) => owner.versions.methods({ versionId: v.id }))))
        .map((m) => m.markdown)
        .sort(),
    );
    expect(strFromU8(files["README.txt"]!)).toContain("experiments/<name>-v<N>-methods.md");
    // And the study's own, as its Methods tab shows it.
    expect(strFromU8(files["methods.md"]!)).toBe((await owner.studies.methods({ studyId: study.id })).markdown);
    expect(Object.keys(files).join()).not.toContain(withdrawnTrial.id);
    expect(JSON.parse(strFromU8(files[`trials/${trial.id}.json`]!))).toMatchObject({
      protocol: { steps: [{ name: "Hello" }] },
      questionnaires: [],
    });
    await owner.studies.update({
      studyId: study.id,
      settings: { blinding: { conditionsFromWizards: false, resultsUntilComplete: true } },
    });
    await expect(f.routeApi("researcher").studies.exportArchive({ studyId: study.id })).rejects.toMatchObject({
      code: "FORBIDDEN",
    });
  });
});

describe("participants' demographics and consent", () => {
  it("checks answers against the study's fields and records which consent document was agreed to", async () => {
    const study = await f.newStudy();
    await owner.studies.update({
      studyId: study.id,
      settings: {
        consentDocumentVersion: "2026-03 v2",
        demographics: [
          { key: "age", label: "Age", type: "number", options: [] },
          { key: "handedness", label: "Handedness", type: "choice", options: ["left", "right"] },
        ],
      },
    });
    const p = await owner.participants.create({
      studyId: study.id,
      code: "D1",
      demographics: { age: 41, handedness: "left" },
    });
    expect(p).toMatchObject({ demographics: { age: 41, handedness: "left" }, consentVersion: null });
    const given = await owner.participants.update({
      participantId: p.id,
      consentStatus: "given",
      consentDate: new Date(),
    });
    expect(given.consentVersion).toBe("2026-03 v2");
    const error = await f.httpError("owner", "participants.create", {
      studyId: study.id,
      code: "D2",
      demographics: { age: "forty", name: "Jane" },
    });
    expect(error!.message).toBe(
      "Please correct: demographics: Age: must be a number; name: is not a demographic field of this study",
    );
    expect((await owner.participants.list({ studyId: study.id })).map((x) => x.code)).toEqual(["D1"]);
  });
});

describe("sessions", () => {
  it("plans each condition of a within-subject order once, and a second start reopens the same trial", async () => {
    const { study, experiment, condition } = await runningStudy();
    const second = await owner.conditions.create({ studyId: study.id, name: "Still", experimentId: experiment.id });
    await owner.studies.update({
      studyId: study.id,
      settings: { assignment: { strategy: "counterbalanced", perCondition: 1 } },
    });
    const p = await owner.participants.create({
      studyId: study.id,
      code: "W1",
      consentStatus: "given",
      consentDate: new Date(),
    });
    const assigned = await owner.conditions.assign({ participantId: p.id });
    const wizardId = f.people.wizard.id;
    await owner.sessions.schedule({ participantId: p.id, plannedAt: new Date("2026-12-01T10:00:00Z"), wizardId });
    await owner.sessions.schedule({ participantId: p.id, plannedAt: new Date("2026-12-08T10:00:00Z"), wizardId });
    await expect(
      owner.sessions.schedule({ participantId: p.id, plannedAt: new Date(), wizardId }),
    ).rejects.toMatchObject({ code: "CONFLICT" });
    const planned = await owner.sessions.list({ studyId: study.id });
    const names = new Map([
      [condition.id, condition.name],
      [second.id, second.name],
    ]);
    expect(planned.map((s) => s.conditionName)).toEqual(
      (assigned.conditionOrder as string[]).map((id) => names.get(id)),
    );

    const mine = await f.api("wizard").sessions.mine();
    const first = mine.find((s) => s.id === planned[0]!.id)!;
    expect(first).toMatchObject({ participantCode: "W1", studyTitle: study.title, trialId: null });
    const a = await f.api("wizard").sessions.start({ sessionId: first.id });
    const b = await f.api("wizard").sessions.start({ sessionId: first.id });
    expect(b.trialId).toBe(a.trialId);
    await expect(owner.sessions.remove({ sessionId: first.id })).rejects.toMatchObject({
      message: expect.stringMatching(/has started/),
    });
  });

  it("refuses to plan a session before the participant is assigned, or for an observer as wizard", async () => {
    const { study, participant } = await runningStudy();
    await expect(
      owner.sessions.schedule({ participantId: participant.id, plannedAt: new Date(), wizardId: f.people.wizard.id }),
    ).rejects.toMatchObject({
      code: "PRECONDITION_FAILED",
      message: "P001 has no condition yet: assign them first.",
    });
    const [c] = await owner.conditions.list({ studyId: study.id });
    await owner.conditions.assign({ participantId: participant.id, conditionId: c!.id });
    await expect(
      owner.sessions.schedule({ participantId: participant.id, plannedAt: new Date(), wizardId: f.people.observer.id }),
    ).rejects.toMatchObject({ code: "BAD_REQUEST" });
  });
});
