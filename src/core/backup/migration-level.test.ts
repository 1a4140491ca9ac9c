import { describe, expect, it } from "vitest";
import { checkRestoreLevels, migrationLevel, type MigrationLevel } from "./migration-level";

const journal = [
  { tag: "0000_initial", when: 100 },
  { tag: "0001_more", when: 200 },
  { tag: "0002_most", when: 300 },
];
const at = (level: number): MigrationLevel => ({ level, last: level ? journal[level - 1]!.tag : null });

describe("migrationLevel", () => {
  it.each<[string, number[], MigrationLevel]>([
    ["nothing applied", [], at(0)],
    ["the first", [100], at(1)],
    ["all, in any order", [300, 100, 200], at(3)],
    ["the migrator only looks at the latest", [200], at(2)],
  ])("%s", (_, applied, expected) => {
    expect(migrationLevel(journal, applied)).toEqual(expected);
  });

  it("refuses a migration this copy does not know", () => {
    expect(() => migrationLevel(journal, [100, 400])).toThrow("a migration this copy of HRIStudio does not know");
    expect(() => migrationLevel(journal, [150])).toThrow("does not know");
  });
});

describe("checkRestoreLevels", () => {
  it.each<[string, MigrationLevel, MigrationLevel]>([
    ["an empty database", at(3), at(0)],
    ["an older backup into an empty database", at(1), at(0)],
    ["a database migrated to the backup's level", at(2), at(2)],
    ["a backup of an empty database", at(0), at(0)],
  ])("allows %s", (_, backup, target) => {
    expect(() => checkRestoreLevels(journal, backup, target)).not.toThrow();
  });

  it.each<[string, MigrationLevel, MigrationLevel, string]>([
    [
      "a backup from a newer HRIStudio",
      { level: 4, last: "0003_future" },
      at(0),
      "comes from a newer HRIStudio (database migration 0003_future",
    ],
    ["a backup from another line", { level: 2, last: "0001_other" }, at(0), "comes from another line"],
    ["a target set up beyond the backup", at(1), at(3), "already set up at a later migration (0002_most)"],
  ])("refuses %s", (_, backup, target, message) => {
    expect(() => checkRestoreLevels(journal, backup, target)).toThrow(message);
  });
});
