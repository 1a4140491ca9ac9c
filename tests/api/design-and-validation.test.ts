// Saving a design is one transaction that keeps ids; bad input is refused
// with messages that name the field.
import { TRPCError } from "@trpc/server";
import { afterAll, describe, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

async function newExperiment() {
  const study = await f.newStudy();
  return owner.experiments.create({ studyId: study.id, name: "Design", robotId: "nao6-ros2" });
}

async function failure(promise: Promise<unknown>) {
  const error = await promise.then(
    () => null,
    (e: unknown) => e as TRPCError,
  );
  expect(error).toBeInstanceOf(TRPCError);
  return error!;
}

describe("saving a design", () => {
  it("keeps the ids of steps and actions across saves, and removes what was left out", async () => {
    const e = await newExperiment();
    const first = await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [
        { name: "Intro", actions: [{ type: "say", parameters: { text: "Hello" } }, { type: "wave" }] },
        { name: "End", actions: [{ type: "end_trial" }] },
      ],
    });
    const [intro, end] = first.steps;
    const second = await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: first.draftRevision,
      steps: [
        { id: end!.id, name: "End", actions: [{ id: end!.actions[0]!.id, type: "end_trial" }] },
        { id: intro!.id, name: "Intro, renamed", actions: [{ id: intro!.actions[1]!.id, type: "wave" }] },
      ],
    });
    expect(second.steps.map((s) => [s.id, s.name, s.position])).toEqual([
      [end!.id, "End", 0],
      [intro!.id, "Intro, renamed", 1],
    ]);
    expect(second.steps[1]!.actions.map((a) => a.id)).toEqual([intro!.actions[1]!.id]);
    expect(second.draftRevision).toBe(first.draftRevision + 1);
  });

  it("changes nothing when any part of the save is invalid", async () => {
    const e = await newExperiment();
    const saved = await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [{ name: "Kept", actions: [{ type: "say", parameters: { text: "x" } }] }],
    });
    const error = await failure(
      owner.experiments.saveDesign({
        experimentId: e.id,
        baseRevision: saved.draftRevision,
        steps: [
          { name: "New first", actions: [] },
          // A foreign id in the middle: the whole save must roll back.
          { name: "Bad", actions: [{ id: "not-one-of-ours", type: "wave" }] },
        ],
      }),
    );
    expect(error.message).toContain("id");
    expect(await owner.experiments.get({ experimentId: e.id })).toEqual(saved);
  });

  it("refuses a save based on a revision someone else has already replaced", async () => {
    const e = await newExperiment();
    await owner.experiments.saveDesign({ experimentId: e.id, baseRevision: 0, steps: [{ name: "Mine", actions: [] }] });
    const error = await failure(
      f
        .api("researcher")
        .experiments.saveDesign({ experimentId: e.id, baseRevision: 0, steps: [{ name: "Theirs", actions: [] }] }),
    );
    expect(error.code).toBe("CONFLICT");
    expect(error.message).toMatch(/Someone else saved this experiment/);
    expect((await owner.experiments.get({ experimentId: e.id })).steps.map((s) => s.name)).toEqual(["Mine"]);
  });

  it("publishes immutable numbered versions whose hash follows the content, and an unchanged draft as the version it is", async () => {
    const e = await newExperiment();
    await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [{ name: "One", actions: [{ type: "say", parameters: { text: 'He said "{{hi}}" $(rm -rf /)' } }] }],
    });
    const v1 = await owner.versions.publish({ experimentId: e.id });
    // Unchanged since version 1, on the same plugin document: publishing again is version 1, not a copy.
    const again = await owner.versions.publish({ experimentId: e.id });
    expect([again.id, again.version, again.hash]).toEqual([v1.id, 1, v1.hash]);
    expect(v1.hash).toMatch(/^[0-9a-f]{64}$/);
    expect(v1.snapshot.steps[0]!.actions[0]!.parameters.text).toBe('He said "{{hi}}" $(rm -rf /)');
    const draft = await owner.experiments.get({ experimentId: e.id });
    await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: draft.draftRevision,
      steps: draft.steps.map((s) => ({ ...s, name: "Changed" })),
    });
    const v2 = await owner.versions.publish({ experimentId: e.id });
    expect([v2.version, v2.hash === v1.hash]).toEqual([2, false]);
    expect(
      ((await owner.versions.get({ versionId: v1.id })).snapshot as { steps: Array<{ name: string }> }).steps[0]!.name,
    ).toBe("One");
  });

  it("keeps a step's and a question's time limit through a save and into the published version, and none where none was set", async () => {
    const e = await newExperiment();
    const question = {
      options: [
        { id: "yes", label: "Yes" },
        { id: "no", label: "No" },
      ],
    };
    await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [
        {
          name: "Ask",
          timeLimit: { seconds: 60, after: { to: "next" } },
          actions: [{ type: "record_answer", parameters: question, timeLimit: { seconds: 10, after: { to: "end" } } }],
        },
        { name: "Bye", actions: [{ type: "say", parameters: { text: "Bye" } }] },
      ],
    });
    const draft = await owner.experiments.get({ experimentId: e.id });
    expect(draft.steps.map((s) => s.timeLimit)).toEqual([{ seconds: 60, after: { to: "next" } }, undefined]);
    const { snapshot } = await owner.versions.publish({ experimentId: e.id });
    expect(snapshot.steps[0]!.timeLimit).toEqual({ seconds: 60, after: { to: "next" } });
    expect(snapshot.steps[0]!.actions[0]!.timeLimit).toEqual({ seconds: 10, after: { to: "end" } });
    expect("timeLimit" in snapshot.steps[1]!).toBe(false);
    expect("timeLimit" in snapshot.steps[1]!.actions[0]!).toBe(false);
  });
});

describe("input errors a person can read", () => {
  it.each<[string, string, (studyId: string) => unknown, string]>([
    ["an empty study title", "studies.create", () => ({ title: "   " }), "title: Title must not be empty"],
    [
      "a study title that is too long",
      "studies.create",
      () => ({ title: "x".repeat(201) }),
      "title: Title must be at most 200 characters",
    ],
    [
      "an unknown study status",
      "studies.update",
      (studyId) => ({ studyId, status: "finished" }),
      'status: Invalid option: expected one of "draft"|"active"|"completed"|"archived"',
    ],
    [
      "a member role that does not exist",
      "members.add",
      (studyId) => ({ studyId, email: "a@b.org", role: "boss" }),
      "role: must be one of owner, researcher, wizard, observer",
    ],
    [
      "an email that is not one",
      "members.add",
      (studyId) => ({ studyId, email: "nobody", role: "observer" }),
      "email: must be an email address",
    ],
    [
      "a participant code with a space",
      "participants.create",
      (studyId) => ({ studyId, code: "Jane Doe" }),
      "code: Participant code may use letters, digits, '.', '_' and '-' only (no names)",
    ],
    [
      "a missing participant code",
      "participants.create",
      (studyId) => ({ studyId }),
      "code: Participant code is required",
    ],
  ])("%s", async (_name, path, input, expected) => {
    const study = await f.newStudy();
    const error = await f.httpError("owner", path, input(study.id));
    expect(error!.data.code).toBe("BAD_REQUEST");
    expect(error!.message).toBe(`Please correct: ${expected}`);
    expect(error!.data.issues![0]!.field).toBe(expected.split(":")[0]);
  });

  it("names the nested field of an action in a design", async () => {
    const e = await newExperiment();
    const error = await f.httpError("owner", "experiments.saveDesign", {
      experimentId: e.id,
      baseRevision: 0,
      steps: [{ name: "S", actions: [{ type: "say", parameters: "text" }] }],
    });
    expect(error!.message).toBe("Please correct: steps.0.actions.0.parameters: must be an object of named values");
  });

  it("reports a duplicate participant code as a conflict that names the code", async () => {
    const study = await f.newStudy();
    await owner.participants.create({ studyId: study.id, code: "P007" });
    const error = await failure(owner.participants.create({ studyId: study.id, code: "P007" }));
    expect(error.message).toBe("Participant code P007 is already used in this study.");
  });

  it("never lets the last owner go", async () => {
    const study = await f.newStudy();
    const error = await failure(owner.members.remove({ studyId: study.id, userId: f.people.owner.id }));
    expect(error.message).toMatch(/at least one owner/);
  });
});

describe("publishing, files and versions", () => {
  const hostile = `She said "stop" {{text}} \\ $(rm -rf /) \`id\`; echo 'x' > /tmp/y\nnew line`;
  const design = (extra: Array<{ type: string; parameters?: Record<string, unknown> }> = []) => [
    { name: "Greeting", actions: [{ type: "say", parameters: { text: hostile } }, { type: "wave" }, ...extra] },
  ];

  it("refuses to publish a design with problems, says which, and publishes nothing", async () => {
    const e = await newExperiment();
    await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [
        { name: "Intro", actions: [{ type: "say", parameters: {} }] },
        { name: "Empty", actions: [] },
      ],
    });
    const error = await failure(owner.versions.publish({ experimentId: e.id }));
    expect(error.code).toBe("BAD_REQUEST");
    expect(error.message).toMatch(/cannot be published until these 2 problems are fixed/);
    expect(error.message).toMatch(/"Empty" has no actions/);
    expect(await owner.versions.list({ experimentId: e.id })).toEqual([]);
  });

  it("exports a file that imports into another study as the same design, byte for byte, hostile text intact", async () => {
    const e = await newExperiment();
    await owner.experiments.saveDesign({ experimentId: e.id, baseRevision: 0, steps: design() });
    const exported = await owner.experiments.exportFile({ experimentId: e.id });
    expect(exported.fileName).toBe("design.hristudio-experiment.json");
    const other = await f.newStudy();
    const imported = await owner.experiments.importFile({ studyId: other.id, text: exported.text });
    expect(imported.studyId).toBe(other.id);
    const copy = await owner.experiments.get({ experimentId: imported.id });
    expect(copy.steps[0]!.actions[0]!.parameters).toEqual({ text: hostile });
    expect((await owner.experiments.exportFile({ experimentId: imported.id })).text).toBe(exported.text);
  });

  it.each([
    ["not JSON", "{ steps: [", /^This file cannot be imported\. \$: /],
    [
      "a wrong format",
      JSON.stringify({ format: "something-else", formatVersion: 1, experiment: {}, steps: [] }),
      /\$\.format: /,
    ],
    ["a branch to a step that is not in the file", null, /targets/],
  ])("refuses an import of %s, saying where, and stores nothing", async (_name, text, message) => {
    const study = await f.newStudy();
    const file =
      text ??
      JSON.stringify({
        format: "hristudio.experiment",
        formatVersion: 1,
        experiment: { name: "X", description: "", robot: "nao6-ros2" },
        steps: [
          {
            key: "step-1",
            name: "A",
            description: "",
            actions: [{ type: "branch", name: "", parameters: { targets: { yes: "@step-9" } } }],
          },
        ],
      });
    const error = await failure(owner.experiments.importFile({ studyId: study.id, text: file }));
    expect(error.code).toBe("BAD_REQUEST");
    expect(error.message).toMatch(message);
    expect(await owner.experiments.list({ studyId: study.id })).toEqual([]);
  });

  it("refuses an oversized file with its limit", async () => {
    const study = await f.newStudy();
    const error = await f.httpError("owner", "experiments.importFile", {
      studyId: study.id,
      text: "x".repeat(2_000_001),
    });
    expect(error!.message).toBe("Please correct: text: the file must be smaller than 2 MB");
  });

  it("describes what changed between two published versions", async () => {
    const e = await newExperiment();
    const first = await owner.experiments.saveDesign({ experimentId: e.id, baseRevision: 0, steps: design() });
    await owner.versions.publish({ experimentId: e.id });
    const [step] = first.steps;
    await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: first.draftRevision,
      steps: [
        {
          id: step!.id,
          name: "Introduction",
          actions: [{ id: step!.actions[0]!.id, type: "say", parameters: { text: "Hello." } }],
        },
      ],
    });
    await owner.versions.publish({ experimentId: e.id });
    const lines = await owner.versions.diff({ experimentId: e.id, from: 1, to: 2 });
    expect(lines.map((l) => l.kind)).toEqual(expect.arrayContaining(["changed", "removed"]));
    expect(lines.map((l) => l.text).join("\n")).toMatch(/"Greeting" renamed to "Introduction"/);
    expect(await owner.versions.diff({ experimentId: e.id, from: 2, to: 2 })).toEqual([]);
    const missing = await failure(owner.versions.diff({ experimentId: e.id, from: 1, to: 7 }));
    expect(missing.message).toBe("This experiment has no version 7.");
  });
});
