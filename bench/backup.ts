// bench/backup: `npm run backup` and `npm run restore` of a study of 1 GB
// (and of a quarter of that, to show the memory does not follow the size):
// robot samples and events seeded straight in a scratch database, and
// recordings in its media folder: one of 256 MB (a long session's video, which
// a restore streams rather than holds), the rest of 8 MB. Each command runs as a researcher
// runs it (its own process); printed: its time, its throughput and its own
// peak memory (beside the largest of the processes it started and waited for:
// the restore's PostgreSQL, whose shared buffers fill as it loads). Target
// (issue 24): both finish, and the peak memory at 1 GB is within 25 % of the
// quarter's.
// `bun bench/backup.ts 64 256` runs other sizes (MB), smallest first;
// `--largest 512` makes the one long recording 512 MB.
// Takes several minutes: a 1 GB study seeded, backed up and restored, then a quarter of it.
import { readFileSync } from "node:fs";
import { chmod, mkdtemp, rm, stat } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { formatBytes } from "../src/core/backup/manifest";
import { createDatabase } from "../src/store/client";
import { LocalStorage } from "../src/server/media/local-storage";
import { scratchDatabase } from "./support";

const MB = 1024 * 1024;
const args = process.argv.slice(2);
const largestAt = args.indexOf("--largest");
const LARGEST_RECORDING = (largestAt === -1 ? 256 : Number(args.splice(largestAt, 2)[1])) * MB;
const SIZES_MB = args.length ? args.map(Number) : [256, 1024];
/** Of a study's bytes: robot samples, events, recordings. */
const SHARES = { samples: 0.5, events: 0.25, media: 0.25 };
/** About what one row takes in COPY's text, as seeded below. */
const SAMPLE_BYTES = 150;
const EVENT_BYTES = 195;
const RECORDING_BYTES = 8 * MB;
const root = join(import.meta.dirname, "..");

const loadAverage = async () => (await Bun.file("/proc/loadavg").text()).split(" ").slice(0, 3).join(" ");

/** A study of about `bytes`: one trial's robot samples and events, and recordings in `mediaDir`. */
async function seed(url: string, mediaDir: string, bytes: number) {
  const { sql, close } = createDatabase(url, { max: 1 });
  await sql`INSERT INTO studies (id, title) VALUES ('bench', 'Backup bench')`;
  await sql`INSERT INTO experiments (id, study_id, name, robot_id) VALUES ('bench', 'bench', 'E', 'sim')`;
  await sql`INSERT INTO trials (id, study_id, experiment_id, is_rehearsal) VALUES ('bench', 'bench', 'bench', true)`;
  await sql`INSERT INTO trial_samples (trial_id, topic, rel_ms, data)
    SELECT 'bench', '/joint_states', i * 10, jsonb_build_object('name', jsonb_build_array('HeadYaw', 'HeadPitch', 'LShoulderPitch'),
      'position', jsonb_build_array(i * 0.001, -i * 0.002, i * 0.003), 'velocity', jsonb_build_array(0.1, 0.2, 0.3))
    FROM generate_series(1, ${Math.round((bytes * SHARES.samples) / SAMPLE_BYTES)}) i`;
  await sql`INSERT INTO trial_events (trial_id, seq, type, server_time, rel_ms, payload)
    SELECT 'bench', i, 'note.added', now() + i * interval '1 ms', i,
      jsonb_build_object('type', 'note.added', 'text', 'The participant looked at the robot and smiled; wizard noted it ' || i)
    FROM generate_series(1, ${Math.round((bytes * SHARES.events) / EVENT_BYTES)}) i`;
  await close();
  const storage = new LocalStorage(mediaDir);
  const recording = new Uint8Array(RECORDING_BYTES).map((_, i) => (i * 7919) % 251);
  const long = function* () {
    for (let at = 0; at < LARGEST_RECORDING; at += RECORDING_BYTES)
      yield recording.subarray(0, Math.min(RECORDING_BYTES, LARGEST_RECORDING - at));
  };
  await storage.putStream("recordings/bench-long/recording.webm", long(), LARGEST_RECORDING);
  for (let i = 0; i < Math.round((bytes * SHARES.media - LARGEST_RECORDING) / RECORDING_BYTES); i++)
    await storage.put(`recordings/bench-${i}/recording.webm`, recording);
}

/** The process's own peak resident memory so far (Linux's high-water mark), or 0 once it is gone. */
function highWaterMark(pid: number): number {
  try {
    return Number(/VmHWM:\s+(\d+) kB/.exec(readFileSync(`/proc/${pid}/status`, "utf8"))![1]) * 1024;
  } catch {
    return 0;
  }
}

/**
 * One of the commands in its own process: its time, its own peak memory
 * (read every 50 ms: the high-water mark only rises), and the peak of any
 * process it waited for (the restore's PostgreSQL, whose shared buffers fill).
 */
async function run(command: "backup" | "restore", args: string[], env: Record<string, string>) {
  const began = performance.now();
  const child = Bun.spawn([process.execPath, "run", `src/launcher/${command}.ts`, ...args], {
    cwd: root,
    env: { ...process.env, DATABASE_URL: "", HRI_MEDIA_DIR: "", ...env },
    stdout: "pipe",
    stderr: "pipe",
  });
  let peak = 0;
  const sampler = setInterval(() => (peak = Math.max(peak, highWaterMark(child.pid))), 50);
  const [stdout, stderr, code] = await Promise.all([
    new Response(child.stdout).text(),
    new Response(child.stderr).text(),
    child.exited,
  ]);
  clearInterval(sampler);
  if (code !== 0) throw new Error(`npm run ${command} failed (${code}):\n${stderr}`);
  return { seconds: (performance.now() - began) / 1000, peak, withChildren: child.resourceUsage()!.maxRSS, stdout };
}

const line = (what: string, seconds: number, bytes: number, run: { peak: number; withChildren: number }) =>
  console.log(
    `${what.padEnd(36)} ${seconds.toFixed(1).padStart(7)} s  ${(bytes / MB / seconds).toFixed(1).padStart(6)} MB/s  peak memory ${formatBytes(run.peak)} (largest with what it started: ${formatBytes(run.withChildren)})`,
  );

console.log(`load average at the start: ${await loadAverage()}`);
console.log(`the largest recording: ${formatBytes(LARGEST_RECORDING)}`);
const peaks: number[] = [];
for (const sizeMb of SIZES_MB) {
  const database = await scratchDatabase();
  const work = await mkdtemp(join(tmpdir(), "hri-bench-backup-"));
  await chmod(work, 0o755); // The restore's PostgreSQL runs as its own user (under root) and must reach its folder.
  try {
    const source = join(work, "source");
    await seed(database.url, join(source, "media"), sizeMb * MB);
    const backedUp = await run("backup", ["--out", `${work}/`], { DATABASE_URL: database.url, HRI_DATA_DIR: source });
    const file = /The backup is (\S+) /.exec(backedUp.stdout)![1]!;
    const { size } = await stat(file);
    line(`backup of a ${sizeMb} MB study (${formatBytes(size)})`, backedUp.seconds, size, backedUp);
    const restored = await run("restore", [file], { HRI_DATA_DIR: join(work, "restored") });
    line(`restore into an empty data folder`, restored.seconds, size, restored);
    peaks.push(Math.max(backedUp.peak, restored.peak));
  } finally {
    await database.stop();
    await rm(work, { recursive: true, force: true });
  }
}
const ratio = peaks.at(-1)! / peaks[0]!;
console.log(
  `peak memory at ${SIZES_MB.at(-1)} MB over at ${SIZES_MB[0]} MB: ${ratio.toFixed(2)}  target < 1.25: ${ratio < 1.25 ? "met" : "NOT met"}`,
);
console.log(`load average at the end: ${await loadAverage()}`);
