// `npm run backup` and `npm run restore`, run as a researcher runs them (the
// real commands as child processes): a backup taken while the database is up,
// restored into a fresh data folder, gives back every row of every table and
// every recording byte for byte; a restore never writes into a target that
// holds data; a backup from an older migration level restores and migrates up.
// A study far past any buffer backs up while a trial appends and restores
// whole; an interrupted or failed backup leaves no file; a backup never
// replaces a file, and --keep removes only older backups of its own.
import { spawn } from "node:child_process";
import { createHash } from "node:crypto";
import { createReadStream, existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import postgres from "postgres";
import { afterAll, describe, expect, it } from "vitest";
import { DEMO_CHANNELS } from "../api/fixture";
import { appRouter } from "../../src/server/api/root";
import { BackupWriter } from "../../src/server/backup/archive";
import { BackupReader } from "../../src/server/backup/archive-reader";
import { readJournal, migrateTo } from "../../src/server/backup/migrations";
import { MANIFEST_FILE, mediaFile, parseManifest, tableFile } from "../../src/core/backup/manifest";
import { createDatabase } from "../../src/store/client";
import { startEmbeddedPostgres, type EmbeddedDatabase } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { LocalStorage } from "../../src/server/media/local-storage";
import { S3Storage } from "../../src/server/media/s3-storage";
import { seedDemo } from "../../src/server/seed/demo";
import { appendEvents } from "../../src/store/event-store";
import { newPerson, pingOf, TEST_SECRET } from "../api/fixture";
import { BUN, newDataDir } from "../support/app";
import { bareTrial, freshDatabaseUrl } from "../support/db";
import { startS3Server } from "../support/python";

const root = join(import.meta.dirname, "..", "..");
const TRICKY = 'tab\there, a newline\nand a backslash \\ , quotes "\'" , ünïcödé 😀, \\N (not a null)';

/**
 * One of the commands, as `npm run` starts it, with its own environment;
 * `meanwhile` is told of each line of progress, with a way to signal it.
 */
function command(
  name: "backup" | "restore",
  args: string[],
  env: Record<string, string>,
  meanwhile?: (stderr: string, signal: (name: NodeJS.Signals) => void) => void,
) {
  return new Promise<{ code: number | null; stdout: string; stderr: string }>((done) => {
    const child = spawn(BUN, ["run", `src/launcher/${name}.ts`, ...args], {
      cwd: root,
      env: { ...process.env, DATABASE_URL: "", HRI_MEDIA_DIR: "", ...env },
    });
    let stdout = "";
    let stderr = "";
    child.stdout.on("data", (d) => (stdout += d));
    child.stderr.on("data", (d) => {
      stderr += d;
      meanwhile?.(stderr, (signal) => child.kill(signal));
    });
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
/** A new folder under the run's folder, removed when the file's tests are done. */
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
      ping: pingOf(db),
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

  it("refuses a backup whose table lost rows, saying the file is damaged", { timeout: 60_000 }, async () => {
    const reader = await BackupReader.open(file);
    const manifest = parseManifest((await reader.bytes(MANIFEST_FILE)).toString("utf8"));
    // The same backup with the events cut after their first row, at a row's end, so COPY alone would take it.
    const cut = join(folder(), "cut.tar");
    const writer = BackupWriter.create({ file: cut });
    for (const { name } of manifest.tables) {
      const rows = await reader.bytes(tableFile(name));
      await writer.add(tableFile(name), [name === "trial_events" ? rows.subarray(0, rows.indexOf("\n") + 1) : rows]);
    }
    for (const { key } of manifest.media) await writer.add(mediaFile(key), [await reader.bytes(mediaFile(key))]);
    await writer.add(MANIFEST_FILE, [await reader.bytes(MANIFEST_FILE)]);
    writer.finish();
    const result = await command("restore", [cut], { HRI_DATA_DIR: folder() });
    expect(result.stderr).toContain(
      "The table trial_events came back with 1 rows where the backup counted 3: the backup file is damaged.",
    );
    expect(result.code).toBe(1);
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

/** Each table's row count and a hash of its rows as PostgreSQL writes them; `leaveOut` names rows to skip per table. */
async function digests(url: string, leaveOut: Record<string, string> = {}) {
  const sql = postgres(url, { max: 1, onnotice: () => {}, connection: { TimeZone: "UTC" } });
  try {
    const tables = await sql<
      Array<{ name: string }>
    >`SELECT tablename AS name FROM pg_tables WHERE schemaname = 'public' ORDER BY 1`;
    const found: Record<string, string> = {};
    for (const { name } of tables) {
      const [row] = await sql.unsafe<Array<{ rows: number; md5: string }>>(
        `SELECT count(*)::int AS rows, md5(coalesce(string_agg(t::text, E'\\n' ORDER BY t::text), '')) AS md5 FROM "${name}" t ${leaveOut[name] ? `WHERE NOT (${leaveOut[name]})` : ""}`,
      );
      found[name] = `${row!.rows} rows, md5 ${row!.md5}`;
    }
    return found;
  } finally {
    await sql.end();
  }
}

/** Every file of a media folder with the hash of its bytes. */
async function mediaHashes(dir: string) {
  const storage = new LocalStorage(dir);
  const hashes: Record<string, string> = {};
  for (const key of await storage.list("")) {
    const hash = createHash("sha256");
    for await (const chunk of createReadStream(join(dir, key))) hash.update(chunk);
    hashes[key] = hash.digest("hex");
  }
  return hashes;
}

describe("a study far past any buffer, backed up while a trial appends", async () => {
  const source = await freshDatabaseUrl();
  const mediaRoot = folder();
  const { db, sql, close } = createDatabase(source, { max: 2 });
  const [samplesTrial, eventsTrial, appendingTrial] = [await bareTrial(db), await bareTrial(db), await bareTrial(db)];
  // Rows of JSON and text that COPY escapes, by the hundred thousand: tens of MB per table.
  await sql`INSERT INTO trial_samples (trial_id, topic, rel_ms, data)
    SELECT ${samplesTrial}, '/joint_states', i * 10.5, jsonb_build_object('position', jsonb_build_array(i, i * 0.25, -i), 'name', ${TRICKY} || i)
    FROM generate_series(1, 250000) i`;
  await sql`INSERT INTO trial_events (trial_id, seq, type, server_time, rel_ms, payload)
    SELECT ${eventsTrial}, i, 'note.added', '2026-01-01T00:00:00Z'::timestamptz + i * interval '1.5 ms', i * 1.5,
      jsonb_build_object('type', 'note.added', 'text', ${TRICKY} || repeat(' words', 10) || i)
    FROM generate_series(1, 150000) i`;
  const storage = new LocalStorage(join(mediaRoot, "media"));
  const recording = new Uint8Array(16 * 1024 * 1024).map((_, i) => (i * 7919 + (i >> 13)) % 256);
  await storage.put("recordings/long/recording.webm", recording);
  for (const part of [0, 1, 2])
    await storage.put(`recordings/open/chunk-00000${part}`, recording.subarray(part * 999_999, (part + 1) * 999_999));
  await close();
  const env = { DATABASE_URL: source, HRI_DATA_DIR: mediaRoot };

  it("gives back every row and every media byte, the appending trial as one moment of its log", {
    timeout: 120_000,
  }, async () => {
    const appender = createDatabase(source, { max: 1 });
    let appending = true;
    const appended = (async () => {
      for (let seq = 0; appending; )
        seq = (
          await appendEvents(
            appender.db,
            { id: appendingTrial, lastSeq: seq, t0: new Date() },
            [{ type: "note.added", text: `note ${seq}` }],
            null,
          )
        ).at(-1)!.seq;
    })();
    const out = folder();
    const backedUp = await command("backup", ["--out", `${out}/`], env);
    appending = false;
    await appended;
    await appender.close();
    expect(backedUp.stderr).toMatch(/\(trial_samples\): 250,000 rows, \d+\.\d MB\n/);
    expect(backedUp.stderr).toMatch(/\(trial_events\): 150,\d\d\d rows, \d+\.\d MB\n/);
    expect(backedUp.code).toBe(0);
    const [file] = readdirSync(out);

    const fresh = folder();
    const restored = await command("restore", [join(out, file!)], { HRI_DATA_DIR: fresh });
    expect(restored.stderr).toMatch(/\(trial_samples\): 250,000 rows, \d+\.\d MB\n/);
    expect(restored.code).toBe(0);
    const server = await startEmbeddedPostgres({ dataDir: fresh });
    running.push(server);

    const check = postgres(server.url, { max: 1, onnotice: () => {} });
    const seqs = (
      await check<Array<{ seq: number }>>`SELECT seq FROM trial_events WHERE trial_id = ${appendingTrial} ORDER BY seq`
    ).map((r) => r.seq);
    await check.end();
    // The appending trial's log up to the backup's moment, with no gap; every other row exactly as the source holds it.
    expect(seqs).toEqual(seqs.map((_, i) => i + 1));
    const moment = `trial_id = '${appendingTrial}' AND seq > ${seqs.length}`;
    expect(await digests(server.url)).toEqual(await digests(source, { trial_events: moment }));
    expect(await mediaHashes(join(fresh, "media"))).toEqual(await mediaHashes(join(mediaRoot, "media")));
  });

  it.each<NodeJS.Signals>(["SIGINT", "SIGTERM"])(
    "stopped by %s, removes its unfinished file and says so",
    { timeout: 60_000 },
    async (signal) => {
      const out = folder();
      let sent = false;
      const result = await command("backup", ["--out", `${out}/`], env, (stderr, kill) => {
        if (sent || !stderr.includes("Backing up")) return;
        sent = true;
        kill(signal);
      });
      expect(result.stderr).toContain(`Stopped: Interrupted by ${signal}. The unfinished file ${out}/hristudio-`);
      expect(result.stderr).toContain(".tar.part was removed: no backup was written.");
      expect(result.code).toBe(1);
      expect(readdirSync(out)).toEqual([]);
    },
  );

  it("a restore stopped by SIGINT among its media files removes them, rolls its rows back and says so", {
    timeout: 180_000,
  }, async () => {
    const out = folder();
    expect((await command("backup", ["--out", `${out}/`], env)).code).toBe(0);
    const file = join(out, readdirSync(out)[0]!);
    // Into a database and an S3 bucket: each recording goes up part by part, so the signal lands among them.
    const s3 = await startS3Server();
    const bucket = { url: s3.url, bucket: "restored", accessKey: "test", secretKey: "test-secret" };
    const into = {
      DATABASE_URL: await freshDatabaseUrl(),
      HRI_DATA_DIR: folder(),
      HRI_MEDIA_S3_URL: bucket.url,
      HRI_MEDIA_S3_BUCKET: bucket.bucket,
      HRI_MEDIA_S3_ACCESS_KEY: bucket.accessKey,
      HRI_MEDIA_S3_SECRET_KEY: bucket.secretKey,
    };
    const tablesWithRows = async () =>
      Object.entries(await digests(into.DATABASE_URL)).filter(([, digest]) => !digest.startsWith("0 rows"));
    try {
      let sent = false;
      const stopped = await command("restore", [file], into, (stderr, kill) => {
        if (sent || !stderr.includes("media files 1/")) return;
        sent = true;
        kill("SIGINT");
      });
      expect(stopped.stderr).toContain(
        "Stopped: Interrupted by SIGINT. Nothing was restored: the rows loaded so far were rolled back",
      );
      expect(stopped.stderr).not.toMatch(/Error\b|\n\s+at /);
      expect(stopped.code).toBe(1);
      expect(await new S3Storage(bucket).list("")).toEqual([]);
      expect(await tablesWithRows()).toEqual([]);
      // Left as it was: the same restore, let run, fills it.
      expect((await command("restore", [file], into)).code).toBe(0);
      expect(await new S3Storage(bucket).list("")).toHaveLength(4);
      expect(await tablesWithRows()).not.toEqual([]);
    } finally {
      s3.stop();
    }
  });

  it("fails when its database connection is cut mid-table, and leaves no file", { timeout: 60_000 }, async () => {
    const out = folder();
    const admin = postgres(source, { max: 1, onnotice: () => {} });
    let cut = false;
    const backup = command("backup", ["--out", `${out}/`], env);
    for (let done = false; !cut && !done; ) {
      const rows = await admin`SELECT pg_terminate_backend(pid) AS cut FROM pg_stat_activity
        WHERE datname = current_database() AND pid <> pg_backend_pid() AND query LIKE 'COPY "trial_samples"%'`;
      cut = rows.some((r) => r.cut);
      done = await Promise.race([backup.then(() => true), new Promise<boolean>((r) => setTimeout(() => r(false), 20))]);
    }
    await admin.end();
    const result = await backup;
    expect(cut).toBe(true);
    expect(result.stderr).toContain(
      "Stopped: The connection to the database was lost (was PostgreSQL stopped or restarted?). The unfinished file",
    );
    expect(result.stderr).toContain("was removed: no backup was written.");
    expect(result.stderr).not.toMatch(/Error\b|\n\s+at /);
    expect(result.code).toBe(1);
    expect(readdirSync(out)).toEqual([]);
  });
});

describe("a backup never replaces a file", async () => {
  const env = { DATABASE_URL: await freshDatabaseUrl(), HRI_DATA_DIR: folder() };
  const isBackup = (name: string) => /^hristudio-[\d-]+\.tar$/.test(name);
  const manifestOf = async (file: string) =>
    parseManifest((await (await BackupReader.open(file)).bytes(MANIFEST_FILE)).toString("utf8"));

  it("gives two backups started together two names, both whole", { timeout: 60_000 }, async () => {
    const out = folder();
    const results = await Promise.all([1, 2].map(() => command("backup", ["--out", `${out}/`], env)));
    expect(results.map((r) => r.code)).toEqual([0, 0]);
    const files = readdirSync(out);
    expect(files.filter(isBackup)).toHaveLength(2);
    for (const file of files) expect((await manifestOf(join(out, file))).format).toBe("hristudio-backup");
  });

  it("moves on to the next name when one is taken in the same millisecond", async () => {
    const out = folder();
    const now = new Date("2026-11-26T23:47:12.045Z");
    writeFileSync(join(out, "hristudio-2026-11-26-234712-045.tar"), "someone else's");
    const writers = [BackupWriter.create({ folder: out, now }), BackupWriter.create({ folder: out, now })];
    for (const writer of writers) writer.finish();
    expect(readdirSync(out).sort()).toEqual([
      "hristudio-2026-11-26-234712-045-2.tar",
      "hristudio-2026-11-26-234712-045-3.tar",
      "hristudio-2026-11-26-234712-045.tar",
    ]);
    expect(readFileSync(join(out, "hristudio-2026-11-26-234712-045.tar"), "utf8")).toBe("someone else's");
  });

  it("leaves a file that appeared at its name while it was written, and removes itself", () => {
    const file = join(folder(), "study.tar");
    const writer = BackupWriter.create({ file });
    writeFileSync(file, "appeared meanwhile");
    expect(() => writer.finish()).toThrow(`A file appeared at ${file} while the backup was written`);
    expect(readFileSync(file, "utf8")).toBe("appeared meanwhile");
    expect(existsSync(`${file}.part`)).toBe(false);
  });

  it("refuses --out naming a file that exists, and leaves it as it was", { timeout: 60_000 }, async () => {
    const file = join(folder(), "study.tar");
    writeFileSync(file, "last week's backup");
    const result = await command("backup", ["--out", file], env);
    expect(result.stderr).toContain(`There is a file at ${file} already: a backup never replaces a file.`);
    expect(result.code).toBe(1);
    expect(readFileSync(file, "utf8")).toBe("last week's backup");
    expect(existsSync(`${file}.part`)).toBe(false);
  });

  it("with --keep 2, removes the older backups of its folder and nothing else", { timeout: 90_000 }, async () => {
    const out = folder();
    writeFileSync(join(out, "study.tar"), "named by hand");
    const made: string[] = [];
    for (const _ of [1, 2, 3]) {
      const result = await command("backup", ["--out", `${out}/`, "--keep", "2"], env);
      expect(result.code).toBe(0);
      made.push(/The backup is (\S+) /.exec(result.stdout)![1]!);
    }
    expect(readdirSync(out).sort()).toEqual([...made.slice(1).map((f) => f.slice(out.length + 1)), "study.tar"].sort());
  });
});
