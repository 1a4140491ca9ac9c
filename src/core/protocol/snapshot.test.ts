import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import { hashCanonical } from "./canonical";
import { DOCUMENT_VERSION } from "./document";
import { readSnapshot, snapshotOf } from "./snapshot";

describe("the snapshot of a design", () => {
  const design = { ...storytellerDraft(), id: "exp-1" };

  it("keeps the draft's fields only, whatever else a stored design carries", () => {
    const stored = {
      ...design,
      studyId: "study-1",
      revision: 7,
      steps: design.steps.map((s, i) => ({
        ...s,
        position: i,
        actions: s.actions.map((a) => ({ ...a, createdAt: new Date(0) })),
      })),
    };
    expect(snapshotOf(stored)).toEqual(snapshotOf(design));
    expect(Object.keys(snapshotOf(stored).experiment).sort()).toEqual(["description", "id", "name", "robotId"]);
  });

  it("says where every step leads, so a published version never depends on a default", () => {
    const { steps } = snapshotOf({ ...design, steps: design.steps.map(({ after: _, ...s }) => s) });
    expect(steps.every((s) => s.after?.to === "next")).toBe(true);
  });

  it("hashes the same design the same way", () => {
    expect(hashCanonical(snapshotOf(design))).toBe(hashCanonical(snapshotOf(structuredClone(design))));
  });
});

describe("reading a stored snapshot", () => {
  it("upgrades schema version 1 (robotPluginId, no after) and leaves its stored bytes alone", () => {
    const v1 = {
      schemaVersion: 1,
      experiment: { id: "e", name: "E", description: "", robotPluginId: "nao6-ros2" },
      steps: [{ id: "s", name: "S", description: "", actions: [] }],
    };
    const before = JSON.stringify(v1);
    const read = readSnapshot(v1);
    expect(read.schemaVersion).toBe(DOCUMENT_VERSION);
    expect(read.experiment).toEqual({ id: "e", name: "E", description: "", robotId: "nao6-ros2" });
    expect(read.steps[0]!.after).toBeUndefined();
    expect(JSON.stringify(v1)).toBe(before);
  });

  it("reads today's version as it is", () => {
    const today = snapshotOf({ ...storytellerDraft(), id: "e" });
    expect(readSnapshot(today)).toBe(today);
  });

  it("refuses a version it does not know, rather than guessing", () => {
    expect(() => readSnapshot({ schemaVersion: 9, experiment: {}, steps: [] })).toThrow(/schema version 9/);
  });
});
