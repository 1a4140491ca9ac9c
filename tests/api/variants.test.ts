// Conditions in one experiment, as a research team would set them up through
// the API: a tutor study whose two conditions differ by one feedback line and
// one goodbye step. Saved, published and reopened with its variants; a trial
// of each condition gets its own; a name that is no condition of the experiment is refused.
import { afterAll, describe, expect, it } from "vitest";
import { hashCanonical } from "../../src/core/protocol/canonical";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

async function tutorStudy() {
  const study = await f.newStudy("Tutor study");
  const experiment = await owner.experiments.create({ studyId: study.id, name: "Tutor", robotId: "nao6-ros2" });
  const warm = await owner.conditions.create({ studyId: study.id, name: "Warm tutor", experimentId: experiment.id });
  const neutral = await owner.conditions.create({
    studyId: study.id,
    name: "Neutral tutor",
    experimentId: experiment.id,
  });
  await owner.studies.update({ studyId: study.id, settings: { assignment: { strategy: "fixed", perCondition: 1 } } });
  return { study, experiment, warm, neutral };
}

const design = (variant: string) => [
  {
    name: "Feedback",
    description: "",
    actions: [
      {
        type: "say",
        parameters: { text: "Well done." },
        variants: { [variant]: { parameters: { text: "Well done, you are doing great!" } } },
      },
    ],
  },
  {
    name: "Goodbye",
    description: "",
    actions: [{ type: "say", parameters: { text: "Goodbye." } }],
    variants: {
      "Neutral tutor": { actions: [{ id: "bye-neutral", type: "say", name: "", parameters: { text: "The end." } }] },
    },
  },
];

/** Saves the design with the warm tutor's variants as the experiment's draft. */
async function saveWarm(experimentId: string) {
  const draft = await owner.experiments.get({ experimentId });
  await owner.experiments.saveDesign({ experimentId, baseRevision: draft.draftRevision, steps: design("Warm tutor") });
}

describe("an experiment whose conditions vary", () => {
  it("is saved, published and reopened with each condition's variants, which the hash covers", async () => {
    const { experiment } = await tutorStudy();
    await saveWarm(experiment.id);
    const reopened = await owner.experiments.get({ experimentId: experiment.id });
    expect(reopened.steps[0]!.actions[0]!.variants).toEqual({
      "Warm tutor": { parameters: { text: "Well done, you are doing great!" } },
    });
    expect(reopened.steps[1]!.variants!["Neutral tutor"]!.actions[0]!.parameters).toEqual({ text: "The end." });
    const published = await owner.versions.publish({ experimentId: experiment.id });
    const version = await owner.versions.get({ versionId: published.id });
    expect(version.snapshot.steps[0]!.actions[0]!.variants).toEqual(reopened.steps[0]!.actions[0]!.variants);
    expect(version.snapshot.steps[1]!.variants).toEqual(reopened.steps[1]!.variants);
    expect(hashCanonical(version.snapshot)).toBe(version.hash);
  });

  it("gives a trial in each condition that condition's variants, and one of no variant the shared design", async () => {
    const { study, experiment, warm, neutral } = await tutorStudy();
    await saveWarm(experiment.id);
    const version = await owner.versions.publish({ experimentId: experiment.id });
    const said = async (conditionId: string, code: string) => {
      const participant = await owner.participants.create({
        studyId: study.id,
        code,
        consentStatus: "given",
        consentDate: new Date(),
      });
      await owner.conditions.assign({ participantId: participant.id, conditionId });
      const trial = await owner.trials.create({ versionId: version.id, participantId: participant.id });
      const { protocol } = await owner.trials.get({ trialId: trial.id });
      return protocol!.steps.flatMap((s) => s.actions.map((a) => [a.parameters.text, a.variant ?? null]));
    };
    expect(await said(warm.id, "W1")).toEqual([
      ["Well done, you are doing great!", "Warm tutor"],
      ["Goodbye.", null],
    ]);
    expect(await said(neutral.id, "N1")).toEqual([
      ["Well done.", null],
      ["The end.", "Neutral tutor"],
    ]);
    const rehearsal = await owner.trials.rehearse({ experimentId: experiment.id, condition: "Warm tutor" });
    const rehearsed = await owner.trials.get({ trialId: rehearsal.id });
    expect(rehearsed.protocol!.steps[0]!.actions[0]!.parameters.text).toBe("Well done, you are doing great!");
  });

  it("refuses a variant for another study's condition, and a rehearsal as one", async () => {
    const { experiment } = await tutorStudy();
    const other = await f.newStudy("Another study");
    const elsewhere = await owner.experiments.create({ studyId: other.id, name: "Other", robotId: "nao6-ros2" });
    await owner.conditions.create({ studyId: other.id, name: "Robot tutor", experimentId: elsewhere.id });
    const draft = await owner.experiments.get({ experimentId: experiment.id });
    const saving = owner.experiments.saveDesign({
      experimentId: experiment.id,
      baseRevision: draft.draftRevision,
      steps: design("Robot tutor"),
    });
    await expect(saving).rejects.toThrow(
      'Please correct: variants: "Robot tutor" is not a condition of this study that runs this experiment',
    );
    expect((await owner.experiments.get({ experimentId: experiment.id })).steps).toEqual([]);
    await owner.experiments.saveDesign({
      experimentId: experiment.id,
      baseRevision: draft.draftRevision,
      steps: design("Warm tutor"),
    });
    await expect(owner.trials.rehearse({ experimentId: experiment.id, condition: "Robot tutor" })).rejects.toThrow(
      '"Robot tutor" is not a condition of this study that runs this experiment',
    );
  });
});
