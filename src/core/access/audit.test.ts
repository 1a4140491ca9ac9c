import { describe, expect, it } from "vitest";
import { actionWords, detailLines } from "./audit";

describe("detailLines", () => {
  it.each([
    ["no details", {}, []],
    [
      "plain values",
      { role: "wizard", seed: 7, blinded: true, reason: null },
      [
        ["role", "wizard"],
        ["seed", "7"],
        ["blinded", "yes"],
        ["reason", "none"],
      ],
    ],
    [
      "nested changes",
      { from: "observer", settings: { blinding: { conditionsFromWizards: false } } },
      [
        ["from", "observer"],
        ["settings.blinding.conditionsFromWizards", "no"],
      ],
    ],
    [
      "a list of values on one line",
      { errors: ["a.json: bad", "b.json: bad"] },
      [["errors", "a.json: bad, b.json: bad"]],
    ],
    [
      "a list of records, numbered",
      { changes: [{ robotId: "nao6", change: "added" }] },
      [
        ["changes 1.robotId", "nao6"],
        ["changes 1.change", "added"],
      ],
    ],
    ["an empty list", { errors: [] }, [["errors", "none"]]],
  ])("%s", (_, details, lines) => {
    expect(detailLines(details)).toEqual(lines);
  });

  it("cuts a long list and says how many lines are left", () => {
    const lines = detailLines({
      changes: Array.from({ length: 20 }, (_, i) => `robot-${i}`).map((robotId) => ({ robotId })),
    });
    expect(lines).toHaveLength(12);
    expect(lines.at(-1)).toEqual(["…", "9 more"]);
  });
});

describe("actionWords", () => {
  it("says what a known action did and leaves an unknown one as it is", () => {
    expect(actionWords("member.role")).toBe("changed a member's role");
    expect(actionWords("robot.teleport")).toBe("robot.teleport");
  });
});
