import { describe, expect, it } from "vitest";
import { BACKUP_FORMAT, countsOf, describeCounts, formatBytes, parseManifest, type BackupManifest } from "./manifest";

const manifest: BackupManifest = {
  format: BACKUP_FORMAT,
  version: 1,
  createdAt: "2026-03-01T12:00:00.000Z",
  migrations: { level: 6, last: "0005_isolation" },
  tables: [
    { name: "studies", columns: ["id", "title"], rows: 2 },
    { name: "trials", columns: ["id"], rows: 3 },
    { name: "trial_events", columns: ["id"], rows: 40 },
    { name: "media_recordings", columns: ["id"], rows: 1 },
  ],
  sequences: [{ name: "trial_events_id_seq", value: "9007199254740993", called: true }],
  media: [
    { key: "recordings/a.webm", size: 1024 },
    { key: "recordings/a/chunk-000000", size: 512 },
  ],
};

describe("the backup manifest", () => {
  it("reads back what was written", () => {
    expect(parseManifest(JSON.stringify(manifest))).toEqual(manifest);
  });

  it.each([
    ["not JSON", "{", "is not JSON"],
    ["another file", JSON.stringify({ hello: 1 }), "not an HRIStudio backup"],
    ["a newer format", JSON.stringify({ ...manifest, version: 2 }), "written by a newer HRIStudio (backup format 2"],
    [
      "a damaged table list",
      JSON.stringify({ ...manifest, tables: [{ name: "x", rows: -1 }] }),
      "manifest.json is damaged: tables.0.columns",
    ],
    [
      "a sequence that is not a number",
      JSON.stringify({ ...manifest, sequences: [{ name: "s", value: "1e3", called: true }] }),
      "sequences.0.value",
    ],
  ])("refuses %s plainly", (_, text, message) => {
    expect(() => parseManifest(text)).toThrow(message);
  });

  it("counts what a researcher checks", () => {
    expect(countsOf(manifest)).toEqual({
      studies: 2,
      trials: 3,
      events: 40,
      recordings: 1,
      mediaFiles: 2,
      mediaBytes: 1536,
    });
    expect(describeCounts(countsOf(manifest))).toBe(
      "2 studies, 3 trials, 40 events, 1 recording (2 media files, 1.5 KB)",
    );
    expect(
      describeCounts(countsOf({ ...manifest, tables: [{ name: "studies", columns: ["id"], rows: 1 }], media: [] })),
    ).toBe("1 study, 0 trials, 0 events, 0 recordings (0 media files, 0 bytes)");
  });

  it.each([
    [0, "0 bytes"],
    [1023, "1023 bytes"],
    [1024, "1.0 KB"],
    [5 * 1024 ** 3, "5.0 GB"],
  ])("writes %i bytes as %s", (bytes, text) => {
    expect(formatBytes(bytes)).toBe(text);
  });
});
