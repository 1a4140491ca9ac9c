// Recordings on the server: parts stored as they come, joined in order when
// finished (a missing part is named, not papered over), the duration written
// into WebM, the size limit kept, and nothing of a part lost on a resend. A
// recording whose page went away is finished by the server from the parts it
// holds: after a silence, at the trial's end, and at the web server's start.
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { webmDuration } from "../../src/core/media/webm-duration";
import { finishLeftOver, GONE_AFTER_MS, keepFinishingLeftOver, LAST_PART_MS } from "../../src/server/media/left-over";
import { finishRecording } from "../../src/server/media/finish";
import { LocalStorage } from "../../src/server/media/local-storage";
import { chunkKey, partArrived } from "../../src/server/media/recordings";
import { mediaRecordings, trials } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { heldDuring } from "../support/memory";
import { scratchFolder } from "../support/scratch";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

// A WebM as Chrome's MediaRecorder writes it (no duration), cut in two parts.
const webm = new Uint8Array([
  0x1a, 0x45, 0xdf, 0xa3, 0x84, 0x42, 0x82, 0x81, 0x77, 0x18, 0x53, 0x80, 0x67, 0x01, 0xff, 0xff, 0xff, 0xff, 0xff,
  0xff, 0xff, 0x15, 0x49, 0xa9, 0x66, 0x87, 0x2a, 0xd7, 0xb1, 0x83, 0x0f, 0x42, 0x40, 0x1f, 0x43, 0xb6, 0x75, 0x83,
  0xe7, 0x81, 0x00,
]);

async function trial() {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  return owner.trials.create({ versionId: version.id });
}

describe("recordings", () => {
  it("joins the parts in order into one file that declares its duration", async () => {
    const t = await trial();
    const { recordingId } = await owner.recordings.start({
      trialId: t.id,
      kind: "video",
      mimeType: "video/webm;codecs=vp8",
    });
    await owner.recordings.setOffset({ recordingId, offsetMs: -140 });
    const key = `recordings/${recordingId}`;
    await f.media.storage.put(chunkKey(key, 1), webm.subarray(20), "video/webm");
    await expect(owner.recordings.finish({ recordingId, durationMs: 4200 })).rejects.toMatchObject({
      code: "PRECONDITION_FAILED",
      message: expect.stringMatching(/^Parts 0 of this recording have not arrived yet/),
    });
    await f.media.storage.put(chunkKey(key, 0), new Uint8Array([9, 9]), "video/webm");
    await f.media.storage.put(chunkKey(key, 0), webm.subarray(0, 20), "video/webm");
    await owner.recordings.finish({ recordingId, durationMs: 4200 });
    const { storageKey } = await owner.recordings.media({ recordingId });
    const bytes = (await f.media.storage.get(storageKey))!;
    expect(webmDuration(bytes)).toBeCloseTo(4200, 3);
    expect(await f.media.storage.list(`${key}/`)).toEqual([]);
    expect(await owner.recordings.list({ trialId: t.id })).toMatchObject([
      { id: recordingId, status: "complete", offsetMs: -140, durationMs: 4200, sizeBytes: bytes.length },
    ]);
    await expect(owner.recordings.chunkTarget({ recordingId })).rejects.toMatchObject({ code: "CONFLICT" });
  });

  it("joins a long recording a part at a time, never holding the whole of it", async () => {
    const t = await trial();
    const { recordingId } = await owner.recordings.start({ trialId: t.id, kind: "video", mimeType: "video/webm" });
    const media = { storage: new LocalStorage(scratchFolder("media-")), maxBytes: 64 * 1024 * 1024 };
    const key = `recordings/${recordingId}`;
    const part = new Uint8Array(1024 * 1024).map((_, i) => (i * 7) % 256);
    await media.storage.put(chunkKey(key, 0), webm);
    for (let i = 1; i <= 32; i++) await media.storage.put(chunkKey(key, i), part);
    const { result, held } = await heldDuring(() => finishRecording(db, media, recordingId, { durationMs: 60_000 }));
    const file = (await media.storage.get(`${result!.storageKey}.webm`))!;
    expect(file.length).toBe(result!.sizeBytes);
    expect(webmDuration(file)).toBeCloseTo(60_000, 3);
    expect(Buffer.compare(file.subarray(-part.length), Buffer.from(part))).toBe(0);
    // A part or two of 1 MB, far from the 32 MB of the recording.
    expect(held).toBeLessThan(8 * 1024 * 1024);
  });

  it("refuses a recording larger than the limit, and a type that is not video or audio", async () => {
    const t = await trial();
    const { recordingId } = await owner.recordings.start({ trialId: t.id, kind: "video", mimeType: "video/mp4" });
    await f.media.storage.put(
      chunkKey(`recordings/${recordingId}`, 0),
      new Uint8Array(f.media.maxBytes + 1),
      "video/mp4",
    );
    await expect(owner.recordings.finish({ recordingId, durationMs: 1 })).rejects.toMatchObject({
      code: "PAYLOAD_TOO_LARGE",
      message: expect.stringMatching(/the limit is 8 MB \(HRI_MEDIA_MAX_MB\)/),
    });
    const error = await f.httpError("owner", "recordings.start", {
      trialId: t.id,
      kind: "video",
      mimeType: "application/x-sh",
    });
    expect(error!.message).toBe("Please correct: mimeType: must be a WebM, MP4 or Ogg video or audio type");
  });
});

// A live WebM in three parts, as a recorder sends them: the header and a first cluster, then a cluster each.
// Clusters of unknown size at 0, 3 and 6 s; the last frame 1.5 s into the third: 7.5 s recorded.
const UNKNOWN = [0x01, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff];
const frame = (ms: number) => [0xa3, 0x88, 0x81, (ms >> 8) & 0xff, ms & 0xff, 0x80, 1, 2, 3, 4];
const cluster = (ms: number, frames: number[]) => [
  ...[0x1f, 0x43, 0xb6, 0x75, ...UNKNOWN, 0xe7, 0x82, (ms >> 8) & 0xff, ms & 0xff],
  ...frames.flatMap(frame),
];
const parts = [
  new Uint8Array([...webm.subarray(0, 33), ...cluster(0, [0, 1000, 2000])]),
  new Uint8Array(cluster(3000, [0, 1000, 2000])),
  new Uint8Array(cluster(6000, [0, 1500])),
];
const RECORDED_MS = 7500;

/** A recording of a trial with the parts its page sent before it went away, stored as the chunk route stores them. */
async function leftBehind(options: { sent?: number; offsetMs?: number; ended?: boolean } = {}) {
  const t = await trial();
  const { recordingId } = await owner.recordings.start({ trialId: t.id, kind: "video", mimeType: "video/webm" });
  if (options.offsetMs !== undefined) await owner.recordings.setOffset({ recordingId, offsetMs: options.offsetMs });
  for (const [i, part] of parts.slice(0, options.sent ?? parts.length).entries()) {
    await f.media.storage.put(chunkKey(`recordings/${recordingId}`, i), part, "video/webm");
    await partArrived(db, recordingId, i);
  }
  if (options.ended)
    await db.update(trials).set({ status: "completed", endedAt: new Date() }).where(eq(trials.id, t.id));
  return { trialId: t.id, recordingId };
}
const later = (ms: number) => new Date(Date.now() + ms);
const row = async (recordingId: string) =>
  (await db.select().from(mediaRecordings).where(eq(mediaRecordings.id, recordingId)))[0]!;

/** Finished from its parts: one playable file declaring the length its frames have, the parts gone, marked cut off. */
async function expectFinishedFromParts(recordingId: string) {
  const { storageKey } = await owner.recordings.media({ recordingId });
  const bytes = (await f.media.storage.get(storageKey))!;
  expect(webmDuration(bytes)).toBeCloseTo(RECORDED_MS, 3);
  expect(bytes.length).toBeGreaterThan(parts.reduce((n, p) => n + p.length, 0));
  expect(await f.media.storage.list(`recordings/${recordingId}/`)).toEqual([]);
  expect(await row(recordingId)).toMatchObject({ status: "complete", cutOff: true, durationMs: RECORDED_MS });
}

describe("a recording whose page went away", () => {
  it("is finished by the server from its parts once its recorder has been silent a minute", async () => {
    const { trialId, recordingId } = await leftBehind({ offsetMs: -300 });
    expect(await finishLeftOver(db, f.media, { now: later(GONE_AFTER_MS - 5000) })).toEqual([]);
    const done = await finishLeftOver(db, f.media, { now: later(GONE_AFTER_MS + 1000) });
    expect(done.map((r) => r.id)).toContain(recordingId);
    await expectFinishedFromParts(recordingId);
    expect(await owner.recordings.list({ trialId })).toMatchObject([
      { id: recordingId, status: "complete", cutOff: true, offsetMs: -300, durationMs: RECORDED_MS },
    ]);
    // Its recorder, back after all, finishes it too: it is already finished, once.
    await expect(owner.recordings.finish({ recordingId, durationMs: 9000 })).resolves.toMatchObject({ recordingId });
    expect((await row(recordingId)).durationMs).toBe(RECORDED_MS);
  });

  it("is finished at its trial's end, once its recorder has had its moment to send the last part", async () => {
    const running = await leftBehind();
    const ended = await leftBehind({ ended: true });
    expect(await finishLeftOver(db, f.media, { now: later(LAST_PART_MS - 5000) })).toEqual([]);
    const done = await finishLeftOver(db, f.media, { now: later(LAST_PART_MS + 1000) });
    expect(done.map((r) => r.id)).toEqual([ended.recordingId]);
    await expectFinishedFromParts(ended.recordingId);
    expect((await row(running.recordingId)).status).toBe("recording");
    // Reading the ended trial's recordings shows it finished.
    expect(await owner.recordings.list({ trialId: ended.trialId })).toMatchObject([{ status: "complete" }]);
  });

  it("is finished when the web server starts, if it was left open before", async () => {
    const { recordingId } = await leftBehind();
    await db
      .update(mediaRecordings)
      .set({ lastPartAt: new Date(Date.now() - 2 * GONE_AFTER_MS) })
      .where(eq(mediaRecordings.id, recordingId));
    const said: string[] = [];
    const stop = keepFinishingLeftOver(db, f.media, (line) => said.push(line));
    try {
      // Said once it is finished, its parts removed.
      await expect.poll(() => said.join("\n"), { timeout: 20_000 }).toContain(`The recording ${recordingId}`);
    } finally {
      stop();
    }
    await expectFinishedFromParts(recordingId);
  });

  it("keeps the parts before one that never arrived, and is failed, its parts kept, when none usable arrived", async () => {
    const gapped = await leftBehind({ sent: 2 });
    await f.media.storage.put(chunkKey(`recordings/${gapped.recordingId}`, 3), parts[2]!, "video/webm");
    await finishLeftOver(db, f.media, { now: later(GONE_AFTER_MS + 1000) });
    expect(await row(gapped.recordingId)).toMatchObject({ status: "complete", cutOff: true, durationMs: 5000 });

    const empty = await leftBehind({ sent: 0 });
    await f.media.storage.put(chunkKey(`recordings/${empty.recordingId}`, 1), parts[1]!, "video/webm");
    await finishLeftOver(db, f.media, { now: later(GONE_AFTER_MS + 1000) });
    expect(await row(empty.recordingId)).toMatchObject({ status: "failed", cutOff: true });
    expect(await f.media.storage.list(`recordings/${empty.recordingId}/`)).toHaveLength(1);
  });

  it("tells the wizard's reopened page", async () => {
    const cut = await leftBehind({ sent: 2 });
    const wizard = f.api("wizard");
    // Its page has just closed: the reopened page sees it still open.
    expect(await wizard.recordings.cutOff({ trialId: cut.trialId })).toMatchObject([{ status: "recording" }]);
    await db
      .update(mediaRecordings)
      .set({ lastPartAt: new Date(Date.now() - LAST_PART_MS - 1000) })
      .where(eq(mediaRecordings.id, cut.recordingId));
    const [told] = await wizard.recordings.cutOff({ trialId: cut.trialId });
    expect(told).toMatchObject({ id: cut.recordingId, status: "complete", cutOff: true, durationMs: 5000 });
    expect(told!.stoppedAt).toBeInstanceOf(Date);
  });
});
