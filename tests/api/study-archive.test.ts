// The study's zip is streamed a batch of trials at a time: read back whole,
// every trial's files are there and complete, a large trial included, and
// the batches are cut by events so memory holds about one batch.
import { strFromU8 } from "fflate";
import { afterAll, describe, expect, it } from "vitest";
import { batchesOf } from "../../src/server/studies/archive";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion, unzipArchive } from "./fixture";

describe("batches of trials for the study's zip", () => {
  it.each([
    { trials: [], batches: [] },
    { trials: [{ id: "a", events: 10 }], batches: [["a"]] },
    // Small trials share a batch until it holds 20,000 events.
    {
      trials: [
        { id: "a", events: 12_000 },
        { id: "b", events: 8_000 },
        { id: "c", events: 1 },
      ],
      batches: [["a", "b"], ["c"]],
    },
    // A trial larger than a batch is a batch of its own, and never split.
    {
      trials: [
        { id: "a", events: 5 },
        { id: "b", events: 100_000 },
        { id: "c", events: 5 },
      ],
      batches: [["a"], ["b"], ["c"]],
    },
    // At most 50 trials a batch, however few events they hold.
    {
      trials: Array.from({ length: 120 }, (_, i) => ({ id: `t${i}`, events: 0 })),
      batches: [50, 50, 20].map((n, b) => Array.from({ length: n }, (_, i) => `t${b * 50 + i}`)),
    },
  ])("$trials.length trials make $batches.length batches", ({ trials, batches }) => {
    expect(batchesOf(trials)).toEqual(batches);
  });
});

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

it("a study's zip, streamed in batches, reads back whole with every trial's files and events", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const sizes = [21_000, 3, 0];
  const trials = [];
  for (const [i, size] of sizes.entries()) {
    const participant = await owner.participants.create({
      studyId: study.id,
      code: `P00${i + 1}`,
      consentStatus: "given",
      consentDate: new Date(),
    });
    const trial = await owner.trials.create({ versionId: version.id, participantId: participant.id });
    const sql = db.$client;
    for (let start = 0; start < size; start += 5_000) {
      const rows = Array.from({ length: Math.min(5_000, size - start) }, (_, k) => ({
        trial_id: trial.id,
        seq: start + k + 1,
        type: "note.added",
        server_time: new Date().toISOString(),
        rel_ms: start + k,
        payload: JSON.stringify({ type: "note.added", text: `Note ${start + k + 1}` }),
      }));
      await sql`insert into trial_events ${sql(rows, "trial_id", "seq", "type", "server_time", "rel_ms", "payload")}`;
    }
    trials.push(trial);
  }

  const archive = await owner.studies.exportArchive({ studyId: study.id });
  expect(archive.trials).toBe(3);
  const files = await unzipArchive(archive);
  for (const [i, trial] of trials.entries()) {
    expect(Object.keys(files)).toEqual(
      expect.arrayContaining([`trials/${trial.id}.json`, `trials/${trial.id}-events.csv`, `trials/${trial.id}.eaf`]),
    );
    const record = JSON.parse(strFromU8(files[`trials/${trial.id}.json`]!));
    expect(record.events).toHaveLength(sizes[i]!);
    expect(parseCsv(strFromU8(files[`trials/${trial.id}-events.csv`]!)).filter((r) => r.length > 1)).toHaveLength(
      sizes[i]! + 1,
    );
  }
  // The large trial's events in order, the last one included.
  const big = JSON.parse(strFromU8(files[`trials/${trials[0]!.id}.json`]!));
  expect(big.events.at(-1)).toMatchObject({ seq: 21_000, text: "Note 21000" });
  expect(Object.keys(files)).toEqual(expect.arrayContaining(["README.txt", "study.json", "questionnaire-answers.csv"]));
});
