import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import { hashCanonical } from "./canonical";
import { snapshotOf } from "./snapshot";

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
    expect(Object.keys(snapshotOf(stored).experiment).sort()).toEqual(["description", "id", "name", "robotPluginId"]);
  });

  it("hashes as versions published before it was shared with the designer did", () => {
    expect(hashCanonical(snapshotOf(design))).toBe("2a28dd2b9d6ea00691c948ffcb5e9b09ebbf6fc281b8170e4adbc8a10a8ac61e");
  });
});
