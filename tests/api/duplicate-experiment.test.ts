// Duplicating an experiment within its study or into another: the design with
// fresh ids, its branches and "Then"s pointing at the copy's own steps, and
// nothing of the source's versions, trials or data. An imported file keeps its
// "Then"s the same way. Into another study, reading the source is checked on
// the source's own study and designing on the target.
import { afterAll, describe, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { studyFingerprint, studyRowCounts } from "../support/study-rows";
import { buildFixture, newPerson } from "./fixture";
import { fullStudy } from "./full-study";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

async function quiz() {
  const study = await f.newStudy();
  const experiment = await owner.experiments.create({ studyId: study.id, name: "Quiz", robotId: "nao6-ros2" });
  const [ask, yes, no, bye] = [0, 1, 2, 3].map(() => crypto.randomUUID()) as [string, string, string, string];
  const options = [
    { id: "y", label: "Yes" },
    { id: "n", label: "No" },
  ];
  await owner.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [
      {
        id: ask,
        name: "Ask",
        actions: [
          { type: "record_answer", parameters: { prompt: "Ready?", options } },
          { type: "branch", parameters: { targets: { y: yes, n: no } } },
        ],
      },
      {
        id: yes,
        name: "Yes",
        after: { to: "step", stepId: bye },
        actions: [{ type: "say", parameters: { text: "Good" } }],
      },
      { id: no, name: "No", after: { to: "end" }, actions: [{ type: "say", parameters: { text: "Pity" } }] },
      { id: bye, name: "Bye", actions: [{ type: "say", parameters: { text: "Bye" } }] },
    ],
  });
  await owner.versions.publish({ experimentId: experiment.id });
  return { study, experiment };
}

/** The design's shape with ids replaced by step names, so a copy and its source compare. */
function shape(design: Awaited<ReturnType<typeof owner.experiments.get>>) {
  const name = new Map(design.steps.map((s) => [s.id, s.name]));
  return design.steps.map((s) => ({
    name: s.name,
    after: s.after.to === "step" ? { to: "step", step: name.get(s.after.stepId) } : s.after,
    actions: s.actions.map((a) => ({
      type: a.type,
      parameters:
        a.type === "branch"
          ? Object.fromEntries(Object.entries(a.parameters.targets as object).map(([k, v]) => [k, name.get(v)]))
          : a.parameters,
    })),
  }));
}

it("copies the design with fresh ids, its branches and Thens pointing at its own steps, and no versions or trials", async () => {
  const { study, experiment } = await quiz();
  const source = await owner.experiments.get({ experimentId: experiment.id });
  const copy = await owner.experiments.duplicate({ experimentId: experiment.id });
  expect(copy).toMatchObject({ name: "Quiz (copy)", studyId: study.id, robotId: "nao6-ros2" });
  expect(shape(copy)).toEqual(shape(source));
  const sourceIds = new Set([
    ...source.steps.map((s) => s.id),
    ...source.steps.flatMap((s) => s.actions.map((a) => a.id)),
  ]);
  for (const id of [...copy.steps.map((s) => s.id), ...copy.steps.flatMap((s) => s.actions.map((a) => a.id))])
    expect(sourceIds.has(id)).toBe(false);
  expect(await owner.versions.list({ experimentId: copy.id })).toEqual([]);
  expect((await owner.trials.list({ studyId: study.id })).filter((t) => t.experimentId === copy.id)).toEqual([]);
  // The source is as it was.
  expect(await owner.experiments.get({ experimentId: experiment.id })).toEqual(source);
});

it("imports a file with its Thens", async () => {
  const { study, experiment } = await quiz();
  const { text } = await owner.experiments.exportFile({ experimentId: experiment.id });
  const imported = await owner.experiments.importFile({ studyId: study.id, text });
  expect(shape(await owner.experiments.get({ experimentId: imported.id }))).toEqual(
    shape(await owner.experiments.get({ experimentId: experiment.id })),
  );
});

it("is refused to wizards and observers, and for another study's experiment", async () => {
  const { experiment } = await quiz();
  for (const caller of ["wizard", "observer"] as const)
    await expect(f.api(caller).experiments.duplicate({ experimentId: experiment.id })).rejects.toMatchObject({
      code: "FORBIDDEN",
      message: `As ${caller === "observer" ? "an" : "a"} ${caller} of this study you may not do this.`,
    });
  await expect(f.api("outsider").experiments.duplicate({ experimentId: experiment.id })).rejects.toMatchObject({
    code: expect.stringMatching(/FORBIDDEN|NOT_FOUND/),
  });
});

describe("into another study", async () => {
  // The source has run (participants, a trial with events and samples, an
  // annotation, a recording, answers); the target is a study the caller owns.
  const source = await fullStudy(f);
  const sourceBefore = await studyFingerprint(db, source.study.id);

  it("copies the design under its own name, unpublished, and nothing of the source's run", async () => {
    const target = await f.newStudy("Follow-up");
    const copy = await owner.experiments.duplicate({ experimentId: source.gestures.id, intoStudyId: target.id });
    expect(copy).toMatchObject({ name: "Story with gestures", studyId: target.id, robotId: "nao6-ros2" });
    expect(shape(copy)).toEqual(shape(await owner.experiments.get({ experimentId: source.gestures.id })));
    expect(await studyRowCounts(db, target.id)).toEqual({
      study: 1,
      member: 4,
      experiment: 1,
      step: 2,
      action: 3,
      audit: 1,
    });
    expect(await studyFingerprint(db, source.study.id)).toBe(sourceBefore);
  });

  it("is independent of its source both ways", async () => {
    const target = await f.newStudy("Independent");
    const copy = await owner.experiments.duplicate({ experimentId: source.still.id, intoStudyId: target.id });
    await owner.experiments.saveDesign({
      experimentId: copy.id,
      baseRevision: copy.draftRevision,
      steps: [{ name: "Changed in the copy", actions: [] }],
    });
    expect(await studyFingerprint(db, source.study.id)).toBe(sourceBefore);

    const { experiment } = await quiz();
    const again = await owner.experiments.duplicate({ experimentId: experiment.id, intoStudyId: target.id });
    const copied = shape(again);
    const draft = await owner.experiments.get({ experimentId: experiment.id });
    await owner.experiments.saveDesign({
      experimentId: experiment.id,
      baseRevision: draft.draftRevision,
      steps: [{ name: "Changed in the source", actions: [] }],
    });
    expect(shape(await owner.experiments.get({ experimentId: again.id }))).toEqual(copied);
  });

  it("needs only to read the source: an observer there who designs in the target may copy", async () => {
    const person = await newPerson(db, "reader");
    await owner.members.add({ studyId: source.study.id, email: person.email, role: "observer" });
    const theirs = await f.apiAs(person).studies.create({ title: "Theirs" });
    const copy = await f.apiAs(person).experiments.duplicate({ experimentId: source.still.id, intoStudyId: theirs.id });
    expect(copy.studyId).toBe(theirs.id);
  });

  it("is refused, writing nothing, where the caller cannot design in the target", async () => {
    const person = await newPerson(db, "mixed");
    const api = f.apiAs(person);
    // A researcher of the source; in the target an observer, then a wizard, then nothing.
    await owner.members.add({ studyId: source.study.id, email: person.email, role: "researcher" });
    const target = await f.newStudy("Observed");
    await owner.members.add({ studyId: target.id, email: person.email, role: "observer" });
    let targetBefore = await studyFingerprint(db, target.id);
    await expect(
      api.experiments.duplicate({ experimentId: source.gestures.id, intoStudyId: target.id }),
    ).rejects.toMatchObject({
      code: "FORBIDDEN",
      message:
        "Not copied: in the study you chose to copy into you are an observer, and only its owner and researchers design there.",
    });
    expect(await studyFingerprint(db, target.id)).toBe(targetBefore);
    await owner.members.changeRole({ studyId: target.id, userId: person.id, role: "wizard" });
    targetBefore = await studyFingerprint(db, target.id);
    await expect(
      api.experiments.duplicate({ experimentId: source.gestures.id, intoStudyId: target.id }),
    ).rejects.toMatchObject({ code: "FORBIDDEN", message: expect.stringContaining("you are a wizard") });
    expect(await studyFingerprint(db, target.id)).toBe(targetBefore);
    await owner.members.remove({ studyId: target.id, userId: person.id });
    targetBefore = await studyFingerprint(db, target.id);
    // Not a member at all: the target reads as if it did not exist.
    await expect(
      api.experiments.duplicate({ experimentId: source.gestures.id, intoStudyId: target.id }),
    ).rejects.toMatchObject({ code: "NOT_FOUND", message: expect.stringContaining("No such study") });
    expect(await studyFingerprint(db, target.id)).toBe(targetBefore);
  });

  it("is refused for another study's experiment, whatever the target", async () => {
    // Study B's experiment, into a study the caller owns: the source reads as if it did not exist.
    const victim = f.apiAs(await newPerson(db, "victim"));
    const b = await victim.studies.create({ title: "Victim" });
    const secret = await victim.experiments.create({ studyId: b.id, name: "Secret", robotId: "nao6-ros2" });
    const mine = await f.newStudy("Mine");
    await expect(owner.experiments.duplicate({ experimentId: secret.id, intoStudyId: mine.id })).rejects.toMatchObject({
      code: "NOT_FOUND",
    });
    // And a study id in the usual key still has to be the source's own study.
    await expect(
      owner.experiments.duplicate({ experimentId: source.still.id, intoStudyId: mine.id, studyId: b.id } as never),
    ).rejects.toMatchObject({ code: "BAD_REQUEST" });
    expect((await studyRowCounts(db, mine.id)).experiment).toBeUndefined();
    expect((await studyRowCounts(db, b.id)).experiment).toBe(1);
  });

  it("is refused to a wizard kept blind to the source's conditions", async () => {
    const person = await newPerson(db, "blinded");
    const blind = await f.newStudy("Blind");
    const e = await owner.experiments.create({ studyId: blind.id, name: "Hidden", robotId: "nao6-ros2" });
    await owner.members.add({ studyId: blind.id, email: person.email, role: "wizard" });
    await owner.studies.update({ studyId: blind.id, settings: { blinding: { conditionsFromWizards: true } } });
    const theirs = await f.apiAs(person).studies.create({ title: "Theirs" });
    await expect(
      f.apiAs(person).experiments.duplicate({ experimentId: e.id, intoStudyId: theirs.id }),
    ).rejects.toMatchObject({ code: "FORBIDDEN", message: expect.stringContaining("blinding") });
  });

  it("is refused, plainly, for a robot whose plugin is not installed; within its own study it is still copied", async () => {
    const study = await f.newStudy("Retired");
    const e = await owner.experiments.create({ studyId: study.id, name: "Old robot", robotId: "no-such-robot" });
    const target = await f.newStudy("New");
    await expect(owner.experiments.duplicate({ experimentId: e.id, intoStudyId: target.id })).rejects.toMatchObject({
      code: "PRECONDITION_FAILED",
      message: expect.stringContaining("“Old robot” is for the robot “no-such-robot”, whose plugin is not installed"),
    });
    expect((await studyRowCounts(db, target.id)).experiment).toBeUndefined();
    expect(await owner.experiments.duplicate({ experimentId: e.id })).toMatchObject({ name: "Old robot (copy)" });
  });
});
