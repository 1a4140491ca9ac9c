import { describe, expect, it } from "vitest";
import { type StudyStatus, trialRefusal } from "./status";

describe("which studies run trials", () => {
  it.each<[StudyStatus, RegExp | null]>([
    ["active", null],
    ["draft", /still a draft: rehearse .* set the study to active/],
    ["completed", /completed: its data is kept read-only/],
    ["archived", /archived: its data is kept read-only/],
  ])("a study that is %s", (status, refusal) => {
    const reason = trialRefusal(status);
    if (refusal === null) expect(reason).toBeNull();
    else expect(reason).toMatch(refusal);
  });
});
