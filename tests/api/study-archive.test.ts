// The study's zip is streamed a batch of trials at a time: read back whole,
// every trial's files are there and complete, a large trial included, and
// the batches are cut by events so memory holds about one batch.
import { strFromU8 } from "fflate";
import { afterAll, describe, expect, it } from "vitest";
import { batchesOf } from "../../src/server/studies/archive";
import { trialSamples } from "../../src/store/schema";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion, unzipArchive } from "./fixture";

describe("batches of trials for the study's zip", () => {
  it.each([
    { trials: [], batches: [] },
    { trials: [{ id: "a", rows: 10 }], batches: [["a"]] },
    // Small trials share a batch until it holds 20,000 rows (events and samples).
    {
      trials: [
        { id: "a", rows: 12_000 },
        { id: "b", rows: 8_000 },
        { id: "c", rows: 1 },
      ],
      batches: [["a", "b"], ["c"]],
    },
    // A trial larger than a batch is a batch of its own, and never split.
    {
      trials: [
        { id: "a", rows: 5 },
        { id: "b", rows: 100_000 },
        { id: "c", rows: 5 },
      ],
      batches: [["a"], ["b"], ["c"]],
    },
    // At most 50 trials a batch, however few rows they hold.
    {
      trials: Array.from({ length: 120 }, (_, i) => ({ id: `t${i}`, rows: 0 })),
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
  const trials: { id: string }[] = [];
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
  // The robot's state while the large trial ran: in its record, its samples CSV and the zip.
  await db.insert(trialSamples).values(
    Array.from({ length: 300 }, (_, i) => ({
      trialId: trials[0]!.id,
      topic: i % 3 ? "/joint_states" : "/battery_state",
      relMs: i * 20,
      data: i % 3 ? { name: ["HeadYaw"], position: [i / 100] } : { percentage: 1 - i / 1000 },
    })),
  );

  const archive = await f.routeApi("owner").studies.exportArchive({ studyId: study.id });
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
  expect(big.samples).toHaveLength(300);
  expect(big.samples[1]).toEqual({ topic: "/joint_states", relMs: 20, data: { name: ["HeadYaw"], position: [0.01] } });
  const samplesCsv = strFromU8(files[`trials/${trials[0]!.id}-samples.csv`]!);
  const [header, ...sampleRows] = parseCsv(samplesCsv).filter((r) => r.length > 1);
  expect(header).toEqual(["trial_id", "topic", "rel_ms", "data"]);
  expect(sampleRows).toHaveLength(300);
  expect(JSON.parse(sampleRows[299]![3]!)).toEqual({ name: ["HeadYaw"], position: [2.99] });
  // The trial's own download gives the same file.
  expect((await owner.trials.export({ trialId: trials[0]!.id, format: "samples" })).body).toBe(samplesCsv);
  expect(parseCsv(strFromU8(files[`trials/${trials[2]!.id}-samples.csv`]!)).filter((r) => r.length > 1)).toHaveLength(
    1,
  );
  expect(Object.keys(files)).toEqual(
    expect.arrayContaining(["README.txt", "study.json", "questionnaire-answers.csv", "codebook.csv"]),
  );
  // The codebook names every column of the events CSV the zip holds.
  const events = parseCsv(strFromU8(files[`trials/${trials[0]!.id}-events.csv`]!))[0]!;
  const codebook = parseCsv(strFromU8(files["codebook.csv"]!));
  expect(codebook.filter((r) => r[0] === "trials/<id>-events.csv").map((r) => r[1])).toEqual(events);
});

it("over tRPC's own link, where an answer is one JSON document, the zip is refused plainly: it is a download", async () => {
  const study = await f.newStudy("Zip over the link");
  await expect(f.api("owner").studies.exportArchive({ studyId: study.id })).rejects.toMatchObject({
    code: "BAD_REQUEST",
    message: "This file is a download: fetch it from its download link",
  });
});
