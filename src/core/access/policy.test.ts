import { describe, expect, it } from "vitest";
import { runsAssigned, type StudyRole } from "./policy";

describe("who runs an assigned trial or session", () => {
  it.each<[string, StudyRole, string | null, boolean]>([
    ["a wizard, their own", "wizard", "me", true],
    ["a wizard, one assigned to nobody (starting it makes it theirs)", "wizard", null, true],
    ["a wizard, another wizard's", "wizard", "someone else", false],
    ["a researcher, anyone's", "researcher", "someone else", true],
    ["an owner, anyone's", "owner", "someone else", true],
  ])("%s", (_, role, assigned, runs) => {
    expect(runsAssigned(role, assigned, "me")).toBe(runs);
  });
});
