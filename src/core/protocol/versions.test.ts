import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import { exportExperiment, importExperiment } from "../designer/exchange";
import { rehearse } from "../trial/rehearse";
import { hashCanonical } from "./canonical";
import { DOCUMENT_VERSION, snapshotSchema } from "./document";
import { snapshotOf } from "./snapshot";
import { fieldsAfter, readSnapshot } from "./versions";

// Real stored examples, written by the code of their time (tests/fixtures/README.md).
const fixture = (name: string) => readFileSync(`tests/fixtures/documents/${name}`, "utf8");
const published = (name: string) => JSON.parse(fixture(name)) as { hash: string; snapshot: Record<string, unknown> };

describe("a version published before today's format", () => {
  it.each<[string, number]>([
    ["storyteller.v1.snapshot.json", 1],
    ["storyteller.v2.snapshot.json", 2],
    ["quiz.v2.snapshot.json", 2],
    ["quiz.v3.snapshot.json", 3],
    ["quiz.v4.snapshot.json", 4],
  ])("%s (version %i) still verifies, reads as today's shape and leaves its stored value alone", (name, version) => {
    const { hash, snapshot } = published(name);
    expect(snapshot.schemaVersion).toBe(version);
    expect(hashCanonical(snapshot)).toBe(hash);
    const stored = JSON.stringify(snapshot);
    const read = readSnapshot(snapshot);
    expect(snapshotSchema.safeParse(read).success).toBe(true);
    expect(read.schemaVersion).toBe(DOCUMENT_VERSION);
    expect(JSON.stringify(snapshot)).toBe(stored);
    expect(hashCanonical(snapshot)).toBe(hash);
  });

  it.each(["storyteller.v2.snapshot.json", "quiz.v2.snapshot.json", "quiz.v3.snapshot.json", "quiz.v4.snapshot.json"])(
    "%s: the same design published today hashes as it did, but for the version it names",
    (name) => {
      const { hash, snapshot } = published(name);
      const { experiment, steps } = readSnapshot(snapshot);
      const today = snapshotOf({ ...experiment, steps: structuredClone(steps) });
      expect(hashCanonical({ ...today, schemaVersion: snapshot.schemaVersion })).toBe(hash);
    },
  );

  it("the storyteller of version 1 reads as the same design published today, and runs the same way", () => {
    const old = readSnapshot(published("storyteller.v1.snapshot.json").snapshot);
    const today = snapshotOf({ ...storytellerDraft(), id: "exp-1" });
    expect(old.experiment).toEqual(today.experiment);
    for (const answer of ["correct", "incorrect"]) {
      const answers = { "recall-2": answer };
      expect(rehearse(old, answers)).toEqual(rehearse(today, answers));
    }
  });

  it("a version 3 document (time limits, no loops) reads as it was, but for its version", () => {
    const three = { ...readSnapshot(published("quiz.v2.snapshot.json").snapshot), schemaVersion: 3 };
    three.steps[0]!.timeLimit = { seconds: 10, after: { to: "end" } };
    const stored = JSON.stringify(three);
    expect(readSnapshot(three)).toEqual({ ...three, schemaVersion: DOCUMENT_VERSION });
    expect(JSON.stringify(three)).toBe(stored);
    // Today's version may hold what version 3 could not: a loop.
    three.steps[0]!.after = { to: "again", stepId: three.steps[0]!.id, times: 2, onward: { to: "next" } };
    expect(snapshotSchema.safeParse({ ...three, schemaVersion: DOCUMENT_VERSION }).success).toBe(true);
  });

  it("the quiz of version 2 still runs its rejoin and its end: each answer's path", () => {
    const quiz = readSnapshot(published("quiz.v2.snapshot.json").snapshot);
    const path = (optionId: string) => rehearse(quiz, { "ask-answer": optionId }).steps.map((s) => s.stepId);
    expect(path("red")).toEqual(["ask", "right", "bye"]);
    expect(path("blue")).toEqual(["ask", "wrong", "bye"]);
    expect(rehearse(quiz, { "ask-answer": "green" }).ending).toBe("completed");
  });
});

describe("an exchange file of an earlier format", () => {
  const ids = () => {
    let n = 0;
    return () => `id-${++n}`;
  };

  it.each<[string, string]>([
    ["storyteller.v1.hristudio.json", "storyteller.v2.hristudio.json"],
    ["storyteller.v2.hristudio.json", "storyteller.v2.hristudio.json"],
    ["quiz.v2.hristudio.json", "quiz.v2.hristudio.json"],
    ["quiz.v3.hristudio.json", "quiz.v3.hristudio.json"],
    ["quiz.v4.hristudio.json", "quiz.v4.hristudio.json"],
  ])("%s imports, and exports today as %s did", (name, written) => {
    const imported = importExperiment(fixture(name), ids());
    if (!imported.ok) throw new Error(JSON.stringify(imported.problems));
    expect(exportExperiment(imported.draft)).toBe(
      fixture(written).replace(/"formatVersion": \d+/, `"formatVersion": ${DOCUMENT_VERSION}`),
    );
  });

  it("refuses in a version 1 file a field version 2 brought", () => {
    const file = JSON.parse(fixture("quiz.v2.hristudio.json"));
    file.formatVersion = 1;
    const imported = importExperiment(JSON.stringify(file), ids());
    expect(imported.ok ? [] : imported.problems).toEqual([
      { path: "$.steps[1].after", message: "is not part of an experiment file" },
      { path: "$.steps[3].after", message: "is not part of an experiment file" },
    ]);
  });

  it.each<[number, string, string[]]>([
    [1, "step", ["after", "timeLimit", "variants"]],
    [1, "action", ["timeLimit", "variants"]],
    [2, "step", ["timeLimit", "variants"]],
    // A loop is a value of "after", not a field: a file of version 3 holding one is refused by the after's own check.
    [3, "step", ["variants"]],
    [3, "action", ["variants"]],
    [4, "step", ["variants"]],
    [4, "action", ["variants"]],
    [DOCUMENT_VERSION, "step", []],
  ])("a file of version %i may not carry, in a %s: %j", (version, place, fields) => {
    expect(fieldsAfter(version, place as "step" | "action")).toEqual(fields);
  });
});
