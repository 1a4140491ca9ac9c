import { describe, expect, it } from "vitest";
import { notSeenNotice, removedNotice } from "./changes";

describe("what a sync says of a robot its repository stopped listing", () => {
  it.each([
    [
      "used by no experiment",
      [],
      'lab-bot is no longer listed by the repository "Lab": it is not offered for new experiments any more. Versions published with it keep running with the document they pinned. No experiment uses it.',
    ],
    [
      "used by two",
      ['"A" (study "S")', '"B" (study "T")'],
      'lab-bot is no longer listed by the repository "Lab": it is not offered for new experiments any more. Versions published with it keep running with the document they pinned. Experiments still using it: "A" (study "S"), "B" (study "T"); they keep their published versions, and a new version needs another plugin of lab-bot.',
    ],
  ])("%s", (_name, usedBy, notice) => {
    expect(removedNotice("lab-bot", 'the repository "Lab"', usedBy)).toBe(notice);
  });

  it.each([
    [["a-bot"], "a-bot was not among"],
    [["a-bot", "b-bot"], "a-bot, b-bot were not among"],
  ])("and of robots it did not see when not every file could be read: %j kept", (ids, start) => {
    expect(notSeenNotice(ids)).toMatch(new RegExp(`^${start} the plugins read this time.*kept as before`));
  });
});
