// What a research team sets and where it shows: its own assignment seed (only
// before the first assignment), the consent checkbox's words and a neutral
// study name on the participant's page, and a blind of observers to condition
// (who still code a finished trial afterwards, against its recording).
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { assign } from "../../src/core/studies/assignment";
import { trials } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

const TITLE = "Politeness raises trust H2";
const NEUTRAL = "A study of storytelling";

async function studyWithConditions() {
  const study = await f.newStudy(TITLE);
  await owner.studies.update({ studyId: study.id, description: "We expect polite NAO to be trusted more." });
  const { experiment, version } = await publishedVersion(owner, study.id);
  const polite = await owner.conditions.create({ studyId: study.id, name: "Polite-RB2", experimentId: experiment.id });
  const curt = await owner.conditions.create({ studyId: study.id, name: "Curt-MW9", experimentId: experiment.id });
  const participant = (code: string) =>
    owner.participants.create({ studyId: study.id, code, consentStatus: "given", consentDate: new Date() });
  return { study, version, polite, curt, participant };
}

describe("settings a team sets", () => {
  it("takes the team's own seed before the first assignment, assigns by it, and refuses it afterwards", async () => {
    const { study, polite, curt, participant } = await studyWithConditions();
    await owner.studies.update({
      studyId: study.id,
      settings: { assignment: { strategy: "balanced", perCondition: 1, seed: " prereg-2026-11 " } },
    });
    expect((await owner.studies.get({ studyId: study.id })).settings.assignment.seed).toBe("prereg-2026-11");
    const assigned = await owner.conditions.assign({ participantId: (await participant("S1")).id });
    expect(assigned.assignment).toMatchObject({ seed: "prereg-2026-11", position: 0 });
    const expected = assign({ kind: "balanced", perCondition: 1 }, [polite.name, curt.name], "prereg-2026-11", 0);
    expect(assigned.conditionId).toBe(
      (expected as { condition: string }).condition === polite.name ? polite.id : curt.id,
    );
    await expect(
      owner.studies.update({ studyId: study.id, settings: { assignment: { seed: "another" } } }),
    ).rejects.toMatchObject({
      code: "BAD_REQUEST",
      message:
        "assignment.seed: the seed can only be set before the first assignment (1 participant is assigned already)",
    });
    expect((await owner.studies.get({ studyId: study.id })).settings.assignment.seed).toBe("prereg-2026-11");
  });

  it.each([
    ["an empty seed", { assignment: { seed: "  " } }, "settings.assignment.seed: must not be empty"],
    ["no consent words", { consentAgreement: " " }, "settings.consentAgreement: must not be empty"],
    [
      "a neutral name too long",
      { neutralTitle: "x".repeat(201) },
      "settings.neutralTitle: must be at most 200 characters",
    ],
  ])("refuses %s, naming the field", async (_name, settings, expected) => {
    const study = await f.newStudy();
    const error = await f.httpError("owner", "studies.update", { studyId: study.id, settings });
    expect(error!.data.code).toBe("BAD_REQUEST");
    expect(error!.message).toBe(`Please correct: ${expected}`);
  });

  it("shows participants the neutral name and the study's consent words", async () => {
    const { study, participant } = await studyWithConditions();
    const q = await owner.questionnaires.create({ studyId: study.id, name: "Consent" });
    const draft = (await owner.questionnaires.get({ questionnaireId: q.id })).draft;
    const items = [{ id: "consent", kind: "consent", text: "You may stop at any time.", required: true }];
    await owner.questionnaires.save({
      questionnaireId: q.id,
      definition: { ...draft, sections: [{ ...draft.sections[0]!, items }] },
    });
    await owner.questionnaires.publish({ questionnaireId: q.id });
    const { token } = await owner.questionnaires.createLink({
      questionnaireId: q.id,
      participantId: (await participant("C1")).id,
    });
    const form = f.api("anonymous").form;
    expect(await form.open({ token })).toMatchObject({ studyTitle: TITLE, consentAgreement: "I agree to take part" });
    await owner.studies.update({
      studyId: study.id,
      settings: { neutralTitle: NEUTRAL, consentAgreement: "I have read the sheet and agree to take part" },
    });
    const opened = await form.open({ token });
    expect(opened).toMatchObject({
      studyTitle: NEUTRAL,
      consentAgreement: "I have read the sheet and agree to take part",
    });
    expect(JSON.stringify(opened)).not.toContain(TITLE);
    // The team still sees the study by its title.
    expect((await owner.studies.get({ studyId: study.id })).title).toBe(TITLE);
  });

  it("hides the condition from a blinded observer on every screen, and the title behind the neutral name", async () => {
    const { study, version, polite, curt, participant } = await studyWithConditions();
    await owner.studies.update({
      studyId: study.id,
      settings: { neutralTitle: NEUTRAL, blinding: { conditionsFromObservers: true } },
    });
    const p = await participant("O1");
    const { conditionId } = await owner.conditions.assign({ participantId: p.id, conditionId: polite.id });
    const trial = await owner.trials.create({ versionId: version.id, participantId: p.id });
    expect(conditionId).toBe(polite.id);

    const observer = f.api("observer");
    const heard = JSON.stringify([
      await observer.studies.get({ studyId: study.id }),
      (await observer.studies.mine()).find((s) => s.id === study.id),
      await observer.trials.get({ trialId: trial.id }),
      await observer.trials.list({ studyId: study.id }),
      await observer.participants.list({ studyId: study.id }),
      await observer.sessions.list({ studyId: study.id }),
    ]);
    expect(heard).toContain(NEUTRAL);
    const secrets = [TITLE, "polite NAO", polite.id, polite.name, curt.name, trial.experimentId!];
    expect(secrets.filter((s) => heard.includes(s))).toEqual([]);
    for (const refused of [
      () => observer.conditions.list({ studyId: study.id }),
      () => observer.experiments.list({ studyId: study.id }),
      () => observer.studies.resultsByCondition({ studyId: study.id }),
      () => observer.trials.export({ trialId: trial.id, format: "json" }),
    ])
      await expect(refused()).rejects.toMatchObject({
        code: "FORBIDDEN",
        message: expect.stringContaining("hides its conditions from observers"),
      });

    // A researcher is not an observer: the blind does not reach them. Lifting it shows the observer all again.
    expect((await f.api("researcher").trials.get({ trialId: trial.id })).experimentId).toBe(trial.experimentId);
    await owner.studies.update({ studyId: study.id, settings: { blinding: { conditionsFromObservers: false } } });
    expect((await observer.trials.get({ trialId: trial.id })).experimentId).toBe(trial.experimentId);
    expect((await observer.studies.get({ studyId: study.id })).title).toBe(TITLE);
  });

  it("lets an observer blind to condition code a finished trial afterwards against its recording, the blind kept", async () => {
    const { study, version, polite, curt, participant } = await studyWithConditions();
    await owner.studies.update({ studyId: study.id, settings: { blinding: { conditionsFromObservers: true } } });
    const p = await participant("C1");
    await owner.conditions.assign({ participantId: p.id, conditionId: polite.id });
    const trial = await owner.trials.create({ versionId: version.id, participantId: p.id });
    const { recordingId } = await owner.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
    await f.media.storage.put(`recordings/${recordingId}/chunk-000000`, new Uint8Array([1, 2, 3]), "video/mp4");
    await owner.recordings.finish({ recordingId, durationMs: 1000 });
    await db.update(trials).set({ status: "completed" }).where(eq(trials.id, trial.id));
    const scheme = await owner.coding.createScheme({ studyId: study.id, template: "participant-engagement" });
    const { id: schemeVersionId } = await owner.coding.publishScheme({ codingSchemeId: scheme.id });

    // After the trial: the recording to watch, the scheme to code with, and codes of their own.
    const observer = f.api("observer");
    const recordings = await observer.recordings.list({ trialId: trial.id });
    expect(recordings.map((r) => [r.id, r.status])).toEqual([[recordingId, "complete"]]);
    expect(await observer.recordings.media({ recordingId })).toMatchObject({ mimeType: "video/mp4" });
    const { schemes } = await observer.coding.forTrial({ trialId: trial.id });
    expect(schemes.map((s) => s.versionId)).toEqual([schemeVersionId]);
    const code = { trialId: trial.id, schemeVersionId, setId: "gaze", codeId: "robot", startMs: 200, endMs: 900 };
    const added = await observer.coding.addCode(code);
    const mine = await observer.coding.forTrial({ trialId: trial.id });
    expect(mine.mine.map((c) => [c.id, c.startMs, c.endMs])).toEqual([[added.id, 200, 900]]);

    // Nothing of it names the condition, and the blind stays: results are still refused.
    const heard = JSON.stringify([recordings, mine, added, await observer.trials.get({ trialId: trial.id })]);
    const secrets = [polite.id, polite.name, curt.name, trial.experimentId!, version.id];
    expect(secrets.filter((s) => heard.includes(s))).toEqual([]);
    await expect(observer.coding.codes({ trialId: trial.id })).rejects.toMatchObject({
      code: "FORBIDDEN",
      message: expect.stringContaining("hides its conditions from observers"),
    });
    expect((await owner.studies.get({ studyId: study.id })).settings.blinding.conditionsFromObservers).toBe(true);
  });

  it("shows a wizard blind to condition the neutral name in place of the title", async () => {
    const { study } = await studyWithConditions();
    await owner.studies.update({
      studyId: study.id,
      settings: { neutralTitle: NEUTRAL, blinding: { conditionsFromWizards: true } },
    });
    const wizard = f.api("wizard");
    expect(await wizard.studies.get({ studyId: study.id })).toMatchObject({ title: NEUTRAL, description: "" });
    expect((await wizard.studies.mine()).find((s) => s.id === study.id)).toMatchObject({ title: NEUTRAL });
  });
});
