import { describe, expect, it } from "vitest";
import {
  alsoProvided,
  chooseDocument,
  describeDocument,
  effectiveTrust,
  FIRST_PARTY,
  identityKey,
  latestPerSource,
  shortHash,
} from "./identity";
import type { TrustLevel } from "./types";

describe("effectiveTrust: the lower of the two", () => {
  const cases: Array<[TrustLevel | undefined, TrustLevel | undefined, TrustLevel]> = [
    ["community", "official", "community"],
    ["verified", "official", "verified"],
    ["official", "verified", "verified"],
    ["official", "official", "official"],
    ["official", undefined, "community"],
    [undefined, "official", "community"],
  ];
  it.each(cases)("repository %s, plugin %s → %s", (repository, plugin, expected) => {
    expect(effectiveTrust(repository, plugin)).toBe(expected);
  });
});

const HASH_A = "a".repeat(64);
const HASH_B = "b".repeat(64);
const entry = (robotId: string, source: string, version: string, hash = HASH_A) => ({
  robotId,
  source,
  sourceName: source === FIRST_PARTY ? "the first-party plugins" : `the repository "${source}"`,
  version,
  hash,
});
const shown = (e: ReturnType<typeof entry> | undefined) => (e ? `${e.robotId} ${e.source} ${e.version}` : "none");

describe("identityKey: source, robotId, version and hash, each telling two documents apart", () => {
  const one = entry("nao", FIRST_PARTY, "3.0.0");
  const cases: Array<[string, ReturnType<typeof entry>, boolean]> = [
    ["the same document", entry("nao", FIRST_PARTY, "3.0.0"), true],
    ["another source", entry("nao", "repo-a", "3.0.0"), false],
    ["another robot", entry("pepper", FIRST_PARTY, "3.0.0"), false],
    ["another version", entry("nao", FIRST_PARTY, "3.0.1"), false],
    ["another content", entry("nao", FIRST_PARTY, "3.0.0", HASH_B), false],
  ];
  it.each(cases)("%s", (_, other, same) => {
    expect(identityKey(one) === identityKey(other)).toBe(same);
  });
  it("names a document with its source, version and a short hash", () => {
    expect(shortHash(HASH_A)).toBe("aaaaaaaaaaaa");
    expect(describeDocument(entry("nao", "repo-a", "3.0.0"))).toBe(
      'nao 3.0.0 from the repository "repo-a" (aaaaaaaaaaaa)',
    );
  });
});

describe("latestPerSource: every source keeps its own document of a robot", () => {
  const cases: Array<[string, ReturnType<typeof entry>[], string[]]> = [
    [
      "first-party and a repository with the same robotId and version are both kept",
      [entry("nao", FIRST_PARTY, "3.0.0"), entry("nao", "repo-a", "3.0.0", HASH_B)],
      ["nao first-party 3.0.0", "nao repo-a 3.0.0"],
    ],
    [
      "two repositories with the same robot are both kept, the first installed first",
      [entry("lab", "repo-a", "1.0.0"), entry("lab", "repo-b", "1.0.0"), entry("lab", "repo-b", "2.0.0")],
      ["lab repo-a 1.0.0", "lab repo-b 2.0.0"],
    ],
    [
      "a source's later install replaces its earlier one, never another source's",
      [entry("lab", "repo-a", "1.0.0"), entry("lab", "repo-b", "5.0.0"), entry("lab", "repo-a", "1.1.0")],
      ["lab repo-a 1.1.0", "lab repo-b 5.0.0"],
    ],
  ];
  it.each(cases)("%s", (_, entries, expected) => {
    expect(latestPerSource(entries).map(shown)).toEqual(expected);
  });
});

describe("chooseDocument: the experiment's choice, else the first source", () => {
  const current = [
    entry("nao", FIRST_PARTY, "3.0.0"),
    entry("nao", "repo-a", "3.0.0", HASH_B),
    entry("lab", "repo-a", "1.0.0"),
  ];
  const cases: Array<[string, string, string | null, string]> = [
    ["no choice: first-party", "nao", null, "nao first-party 3.0.0"],
    ["the repository chosen", "nao", "repo-a", "nao repo-a 3.0.0"],
    ["first-party chosen", "nao", FIRST_PARTY, "nao first-party 3.0.0"],
    ["a source that does not offer the robot gives none, not another's", "lab", FIRST_PARTY, "none"],
    ["an unknown robot", "pepper", null, "none"],
  ];
  it.each(cases)("%s", (_, robotId, source, expected) => {
    expect(shown(chooseDocument(current, robotId, source))).toBe(expected);
  });
});

describe("alsoProvided: a sync says, in plain words, when another source offers the robot", () => {
  const firstParty = entry("nao6-ros2", FIRST_PARTY, "3.0.0");
  const cases: Array<[string, ReturnType<typeof entry>, ReturnType<typeof entry>[], string | null]> = [
    [
      "the same robotId and version as a first-party plugin",
      entry("nao6-ros2", "hristudio", "3.0.0", HASH_B),
      [firstParty],
      'nao6-ros2 is also provided by nao6-ros2 3.0.0 from the first-party plugins (aaaaaaaaaaaa) with the same version, 3.0.0: both are kept, told apart by their source and hash; this repository\'s is nao6-ros2 3.0.0 from the repository "hristudio" (bbbbbbbbbbbb). An experiment that has not chosen uses nao6-ros2 3.0.0 from the first-party plugins (aaaaaaaaaaaa). The designer chooses which one an experiment uses.',
    ],
    [
      "the repository that installed the robot first, synced again",
      entry("lab", "repo-a", "1.1.0"),
      [entry("lab", "repo-a", "1.0.0"), entry("lab", "repo-b", "2.0.0", HASH_B)],
      'lab is also provided by lab 2.0.0 from the repository "repo-b" (bbbbbbbbbbbb): both are kept, told apart by their source and hash; this repository\'s is lab 1.1.0 from the repository "repo-a" (aaaaaaaaaaaa). An experiment that has not chosen uses this repository\'s. The designer chooses which one an experiment uses.',
    ],
    ["its own earlier version only", entry("lab", "repo-a", "1.1.0"), [entry("lab", "repo-a", "1.0.0")], null],
    ["a robot nobody else offers", entry("new-bot", "repo-a", "1.0.0"), [firstParty], null],
  ];
  it.each(cases)("%s", (_, offered, current, expected) => {
    expect(alsoProvided(offered, current)).toBe(expected);
  });
});
