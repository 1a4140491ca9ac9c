// Recordings on the server: parts stored as they come, joined in order when
// finished (a missing part is named, not papered over), the duration written
// into WebM, the size limit kept, and nothing of a part lost on a resend.
import { afterAll, describe, expect, it } from "vitest";
import { webmDuration } from "../../src/core/media/webm-duration";
import { chunkKey } from "../../src/server/media/recordings";
import { freshDatabase } from "../support/db";
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
