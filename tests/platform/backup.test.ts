// `npm run backup` and `npm run restore`, run as a researcher runs them (the
// real commands as child processes): a backup taken while the database is up,
// restored into a fresh data folder, gives back every row of every table and
// every recording byte for byte; a restore never writes into a target that
// holds data; a backup from an older migration level restores and migrates up.
import { spawn } from "node:child_process";
import { mkdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import postgres from "postgres";
import { afterAll, describe, expect, it } from "vitest";
import { DEMO_CHANNELS } from "../api/fixture";
import { appRouter } from "../../src/server/api/root";
import { readJournal, migrateTo } from "../../src/server/backup/migrations";
import { createDatabase } from "../../src/store/client";
import { startEmbeddedPostgres, type EmbeddedDatabase } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { LocalStorage } from "../../src/server/media/local-storage";
import { seedDemo } from "../../src/server/seed/demo";
import { appendEvents } from "../../src/store/event-store";
import { newPerson, TEST_SECRET } from "../api/fixture";
import { BUN, newDataDir } from "../support/app";
import { freshDatabaseUrl } from "../support/db";

const root = join(import.meta.dirname, "..", "..");
const TRICKY = 'tab\there, a newline\nand a backslash \\ , quotes "\'" , ünïcödé 😀, \\N (not a null)';

/** One of the commands, as `npm run` starts it, with its own environment. */
function command(name: "backup" | "restore", args: string[], env: Record<string, string>) {
  return new Promise<{ code: number | null; stdout: string; stderr: string }>((done) => {
    const child = spawn(BUN, ["run", `src/launcher/${name}.ts`, ...args], {
      cwd: root,
      env: { ...process.env, DATABASE_URL: "", HRI_MEDIA_DIR: "", ...env },
    });
    let stdout = "";
    let stderr = "";
    child.stdout.on("data", (d) => (stdout += d));
    child.stderr.on("data", (d) => (stderr += d));
    child.on("exit", (code) => done({ code, stdout, stderr }));
  });
}

/** Every row of every table as PostgreSQL writes it (every column, exactly), in a fixed order. */
async function everything(url: string) {
  const sql = postgres(url, { max: 1, onnotice: () => {}, connection: { TimeZone: "UTC" } });
  try {
    const tables = await sql<
      Array<{ name: string }>
    >`SELECT tablename AS name FROM pg_tables WHERE schemaname = 'public' ORDER BY 1`;
    const rows: Record<string, string[]> = {};
    for (const { name } of tables) {
      rows[name] = (await sql.unsafe<Array<{ row: string }>>(`SELECT t::text AS row FROM "${name}" t ORDER BY 1`)).map(
        (r) => r.row,
      );
    }
    return rows;
  } finally {
    await sql.end();
  }
}

async function mediaOf(dir: string) {
  const storage = new LocalStorage(dir);
  const keys = await storage.list("");
  return Object.fromEntries(await Promise.all(keys.map(async (k) => [k, (await storage.get(k))!] as const)));
}

const running: EmbeddedDatabase[] = [];
const folders: string[] = [];
/** A new folder under .tmp, removed when the file's tests are done. */
const folder = () => {
  folders.push(newDataDir());
  return folders.at(-1)!;
};
afterAll(async () => {
  for (const server of running) await server.stop();
  for (const dir of folders) rmSync(dir, { recursive: true, force: true });
});

/** The demo seed, plus a trial with events (text that COPY must escape), robot samples and two recordings. */
async function studyData(url: string, mediaDir: string) {
  const { db, sql, close } = createDatabase(url, { max: 2 });
  try {
    await seedDemo(db, "password-123");
    const person = await newPerson(db, "owner");
    const storage = new LocalStorage(mediaDir);
    const api = appRouter.createCaller({
      db,
      user: person,
      secret: TEST_SECRET,
      runtimeUrl: "ws://127.0.0.1:1",
      media: { storage, maxBytes: 8 * 1024 * 1024 },
      robotChannels: DEMO_CHANNELS,
    });
    const study = await api.studies.create({ title: `Backups: ${TRICKY}` });
    await api.studies.update({ studyId: study.id, status: "active" });
    const e = await api.experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
    await api.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [{ name: "S", actions: [{ type: "say", parameters: { text: TRICKY } }] }],
    });
    const trial = await api.trials.create({ versionId: (await api.versions.publish({ experimentId: e.id })).id });
    await appendEvents(
      db,
      { id: trial.id, lastSeq: 0, t0: null },
      [
        { type: "trial.started" },
        {
          type: "action.requested",
          stepId: null,
          actionId: "a1",
          actionType: "say",
          parameters: { text: TRICKY, big: 2 ** 53 + 1, nothing: null },
          scripted: false,
          deviation: "unscripted",
        },
        { type: "note.added", text: TRICKY },
      ],
      person.id,
    );
    await sql`INSERT INTO trial_samples (trial_id, topic, rel_ms, data) VALUES (${trial.id}, '/joint_states', 0.1 + 0.2, '{"position": [1e-300, -0.0, 12345678901234567890]}')`;
    const video = new Uint8Array(200_000).map((_, i) => (i * 31) % 256);
    const finished = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
    await storage.put(`recordings/${finished.recordingId}/chunk-000000`, video);
    await api.recordings.finish({ recordingId: finished.recordingId, durationMs: 1000 });
    // One still being recorded: its parts are in the store, not yet joined.
    const open = await api.recordings.start({ trialId: trial.id, kind: "audio", mimeType: "audio/ogg" });
    await storage.put(`recordings/${open.recordingId}/chunk-000000`, new Uint8Array([1, 2, 3]));
    return { trialId: trial.id };
  } finally {
    await close();
  }
}

describe("npm run backup, then npm run restore into a fresh data folder", async () => {
  // The platform's data folder with its database up, as while `npm start` runs.
  const dataDir = folder();
  const server = await startEmbeddedPostgres({ dataDir });
  running.push(server);
  await migrateDatabase(server.url);
  const { trialId } = await studyData(server.url, join(dataDir, "media"));
  const file = join(folder(), "backup.tar");

  it("backs up from the running database, showing progress and what it holds", { timeout: 120_000 }, async () => {
    const result = await command("backup", ["--out", file], { HRI_DATA_DIR: dataDir });
    expect(result.stderr).toMatch(/tables 1\/\d+ /);
    expect(result.stderr).toMatch(/media files 2\/2/);
    expect(result.stdout).toContain(
      "Backed up 2 studies, 1 trial, 3 events, 2 recordings (2 media files, 195.3 KB) from the running database in",
    );
    expect(result.code).toBe(0);
  });

  it("restores the same rows, every column, and the same recordings, byte for byte", { timeout: 180_000 }, async () => {
    const fresh = folder();
    const result = await command("restore", [file], { HRI_DATA_DIR: fresh });
    expect(result.stderr).toMatch(/tables (\d+)\/\1 /);
    expect(result.stdout).toContain("Restored 2 studies, 1 trial, 3 events, 2 recordings");
    expect(result.code).toBe(0);

    const restored = await startEmbeddedPostgres({ dataDir: fresh });
    running.push(restored);
    const before = await everything(server.url);
    const after = await everything(restored.url);
    expect(after).toEqual(before);
    expect(after.trial_events!.filter((row) => row.includes(trialId))).toHaveLength(3);
    expect(after.trial_events!.join("")).toContain("ünïcödé 😀");
    expect(await mediaOf(join(fresh, "media"))).toEqual(await mediaOf(join(dataDir, "media")));

    // The sequences carry on where they were: a new sample gets a new id.
    const sql = postgres(restored.url, { max: 1, onnotice: () => {} });
    const [added] =
      await sql`INSERT INTO trial_samples (trial_id, topic, rel_ms, data) VALUES (${trialId}, 't', 1, '{}') RETURNING id`;
    const [{ max }] = (await sql`SELECT max(id)::int AS max FROM trial_samples`) as unknown as [{ max: number }];
    await sql.end();
    expect(Number(added!.id)).toBe(max);
    expect(before.trial_samples).toHaveLength(1);
  });

  it("takes one moment of the database while a trial appends events", { timeout: 180_000 }, async () => {
    const { db, close } = createDatabase(server.url, { max: 1 });
    let writing = true;
    const writer = (async () => {
      for (let seq = 3; writing; )
        seq = (
          await appendEvents(
            db,
            { id: trialId, lastSeq: seq, t0: new Date() },
            [{ type: "note.added", text: `note ${seq}` }],
            null,
          )
        ).at(-1)!.seq;
    })();
    const during = join(folder(), "during.tar");
    const backedUp = await command("backup", ["--out", during], { HRI_DATA_DIR: dataDir });
    writing = false;
    await writer;
    await close();
    expect(backedUp.code).toBe(0);

    const fresh = folder();
    expect((await command("restore", [during], { HRI_DATA_DIR: fresh })).code).toBe(0);
    const restored = await startEmbeddedPostgres({ dataDir: fresh });
    running.push(restored);
    const events = (await everything(restored.url)).trial_events!.filter((row) => row.includes(trialId));
    const source = new Set((await everything(server.url)).trial_events);
    // Events 1..n with no gap, each exactly as the source holds it: a prefix of the log, never a torn one.
    const seqs = events.map((row) => Number(row.split(",")[1])).sort((a, b) => a - b);
    expect(seqs).toEqual(seqs.map((_, i) => i + 1));
    expect(events.every((row) => source.has(row))).toBe(true);
    expect(events.length).toBeGreaterThanOrEqual(3);
  });

  it("refuses a target that holds data, and leaves it as it was", { timeout: 60_000 }, async () => {
    const before = await everything(server.url);
    const result = await command("restore", [file], { HRI_DATA_DIR: dataDir });
    expect(result.code).toBe(1);
    expect(result.stderr).toContain("already holds");
    expect(await everything(server.url)).toEqual(before);
  });

  it("refuses a media folder that holds files, before touching the database", { timeout: 60_000 }, async () => {
    const fresh = folder();
    mkdirSync(join(fresh, "media", "recordings"), { recursive: true });
    writeFileSync(join(fresh, "media", "recordings", "old.webm"), "x");
    const result = await command("restore", [file], { HRI_DATA_DIR: fresh });
    expect(result.code).toBe(1);
    expect(result.stderr).toContain(`The media folder ${join(fresh, "media")} already holds 1 media files`);
  });

  it("refuses a file that is not a backup, saying so", { timeout: 60_000 }, async () => {
    const notBackup = join(folder(), "notes.tar");
    writeFileSync(notBackup, "just some notes".padEnd(2048, " "));
    const result = await command("restore", [notBackup], { HRI_DATA_DIR: folder() });
    expect(result.code).toBe(1);
    expect(result.stderr).toContain("is damaged at byte 0");
  });

  it("refuses a data folder without a database, and writes no file", { timeout: 60_000 }, async () => {
    const out = join(folder(), "nothing.tar");
    const result = await command("backup", ["--out", out], { HRI_DATA_DIR: folder() });
    expect(result.code).toBe(1);
    expect(result.stderr).toContain("There is no database in");
    expect(() => readFileSync(out)).toThrow();
  });
});

describe("a backup of a database through DATABASE_URL at an older migration level", () => {
  it("restores into an empty database and migrates it up", { timeout: 120_000 }, async () => {
    const journal = readJournal();
    const old = await freshDatabaseUrl(null);
    await migrateTo(old, 1);
    const sql = postgres(old, { max: 1, onnotice: () => {} });
    await sql`INSERT INTO "user" (id, name, email, created_at) VALUES ('u1', ${TRICKY}, 'old@example.org', '2020-02-29 12:34:56.789012+00')`;
    await sql`INSERT INTO studies (id, title, created_by) VALUES ('s1', 'An old study', 'u1')`;
    await sql.end();
    const file = join(folder(), "old.tar");
    const backup = await command("backup", ["--out", file], { DATABASE_URL: old, HRI_DATA_DIR: folder() });
    expect(backup.stdout).toContain(`at database migration ${journal[0]!.tag}`);
    expect(backup.code).toBe(0);

    const target = await freshDatabaseUrl(null);
    const result = await command("restore", [file], { DATABASE_URL: target, HRI_DATA_DIR: folder() });
    expect(result.stderr).toContain(`Migrating from ${journal[0]!.tag} up to ${journal.at(-1)!.tag}`);
    expect(result.code).toBe(0);
    const check = postgres(target, { max: 1, onnotice: () => {} });
    const users =
      await check`SELECT name, "user".created_at::text AS created, settings FROM "user" JOIN studies ON studies.created_by = "user".id`;
    const [{ count }] = (await check`SELECT count(*)::int AS count FROM drizzle.__drizzle_migrations`) as unknown as [
      { count: number },
    ];
    await check.end();
    // The name as it was, the time to the microsecond, and the column a later migration added, at its default.
    expect(users).toEqual([
      { name: TRICKY, created: expect.stringMatching(/^2020-02-29 \d\d:34:56\.789012/), settings: {} },
    ]);
    expect(count).toBe(journal.length);
  });
});
