// Duplicating an experiment within its study: the design with fresh ids, its
// branches and "Then"s pointing at the copy's own steps, and nothing of the
// source's versions or trials. An imported file keeps its "Then"s the same way.
import { afterAll, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

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
  expect(shape(imported)).toEqual(shape(await owner.experiments.get({ experimentId: experiment.id })));
});

it("is refused to wizards and observers, and for another study's experiment", async () => {
  const { experiment } = await quiz();
  await expect(f.api("wizard").experiments.duplicate({ experimentId: experiment.id })).rejects.toMatchObject({
    code: "FORBIDDEN",
  });
  await expect(f.api("outsider").experiments.duplicate({ experimentId: experiment.id })).rejects.toMatchObject({
    code: expect.stringMatching(/FORBIDDEN|NOT_FOUND/),
  });
});
