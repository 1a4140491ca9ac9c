import { describe, expect, it } from "vitest";
import { chooseProviders, effectiveTrust, FIRST_PARTY, shadowing } from "./identity";
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

const entry = (robotId: string, source: string, version: string) => ({ robotId, source, sourceName: source, version });

describe("chooseProviders: one source per robot", () => {
  const cases: Array<[string, ReturnType<typeof entry>[], string[]]> = [
    [
      "first-party wins over a repository",
      [entry("nao", FIRST_PARTY, "3.0.0"), entry("nao", "repo-a", "9.0.0")],
      ["nao first-party 3.0.0"],
    ],
    [
      "the first repository to install a robot keeps it",
      [entry("lab", "repo-a", "1.0.0"), entry("lab", "repo-b", "1.0.0"), entry("lab", "repo-b", "2.0.0")],
      ["lab repo-a 1.0.0"],
    ],
    [
      "its own later versions replace its earlier ones",
      [entry("lab", "repo-a", "1.0.0"), entry("lab", "repo-b", "5.0.0"), entry("lab", "repo-a", "1.1.0")],
      ["lab repo-a 1.1.0"],
    ],
    [
      "different robots from different sources",
      [entry("nao", FIRST_PARTY, "3.0.0"), entry("lab", "repo-a", "1.0.0")],
      ["nao first-party 3.0.0", "lab repo-a 1.0.0"],
    ],
  ];
  it.each(cases)("%s", (_, entries, expected) => {
    expect(chooseProviders(entries).map((e) => `${e.robotId} ${e.source} ${e.version}`)).toEqual(expected);
  });
});

describe("shadowing: a repository cannot take another source's robot", () => {
  const owners = [
    { robotId: "nao6-ros2", source: FIRST_PARTY, sourceName: "the first-party plugins" },
    { robotId: "lab-bot", source: "repo-a", sourceName: 'the repository "Lab A"' },
  ];
  const cases: Array<[string, string, string | null]> = [
    [
      "nao6-ros2",
      "repo-b",
      "nao6-ros2 is already provided by the first-party plugins; this repository's copy was not installed.",
    ],
    [
      "lab-bot",
      "repo-b",
      `lab-bot is already provided by the repository "Lab A"; this repository's copy was not installed.`,
    ],
    ["lab-bot", "repo-a", null],
    ["new-bot", "repo-b", null],
  ];
  it.each(cases)("%s offered by %s", (robotId, source, expected) => {
    expect(shadowing(robotId, source, owners)).toBe(expected);
  });
});
