// A finished recording is streamed from media storage by its route, in byte
// ranges so the player can seek (200 whole, 206 a part, 416 past the end),
// with ?download naming the file; the policy still decides who may play it.
// A part stored through its route tells the server its recorder is still there.
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { finishLeftOver, GONE_AFTER_MS } from "../../src/server/media/left-over";
import { mediaRecordings } from "../../src/store/schema";
import { ORIGIN, routeServer } from "../support/routes";
import { publishedVersion } from "./fixture";

const s = await routeServer();
afterAll(s.close);
const media = await import("../../src/app/api/recordings/[recordingId]/media/route");
const chunks = await import("../../src/app/api/recordings/[recordingId]/chunks/[index]/route");
const owner = await s.signIn("owner");
const observer = await s.signIn("observer");
const outsider = await s.signIn("outsider");
const bytes = new Uint8Array(100_000).map((_, i) => (i * 7) % 256);

async function recording(finished: boolean) {
  const api = await s.apiAs(owner);
  const study = await s.f.newStudy();
  const { version } = await publishedVersion(api, study.id);
  const trial = await api.trials.create({ versionId: version.id });
  const { recordingId } = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
  await s.server.media.storage.put(`recordings/${recordingId}/chunk-000000`, bytes, "video/mp4");
  if (finished) await api.recordings.finish({ recordingId, durationMs: 1000 });
  return recordingId;
}

const get = (recordingId: string, who: Headers, headers: Record<string, string> = {}, query = "") =>
  media.GET(
    new Request(`${ORIGIN}/api/recordings/${recordingId}/media${query}`, {
      headers: { cookie: who.get("cookie")!, ...headers },
    }),
    { params: Promise.resolve({ recordingId }) },
  );

const body = async (res: Response) => new Uint8Array(await res.arrayBuffer());

describe("a recording's media route", () => {
  it("streams the whole file with its length, and says it takes ranges", async () => {
    const id = await recording(true);
    const res = await get(id, observer);
    expect(res.status).toBe(200);
    expect(res.body).toBeInstanceOf(ReadableStream);
    expect(Object.fromEntries(res.headers)).toMatchObject({
      "content-type": "video/mp4",
      "content-length": "100000",
      "accept-ranges": "bytes",
    });
    expect(await body(res)).toEqual(bytes);
  });

  it.each([
    ["bytes=10-19", 10, 19],
    ["bytes=99990-", 99990, 99999],
    ["bytes=-5", 99995, 99999],
    ["bytes=99000-200000", 99000, 99999],
  ])("answers %s with 206 and exactly those bytes", async (range, start, end) => {
    const id = await recording(true);
    const res = await get(id, owner, { range });
    expect(res.status).toBe(206);
    expect(res.headers.get("content-range")).toBe(`bytes ${start}-${end}/100000`);
    expect(res.headers.get("content-length")).toBe(String(end - start + 1));
    expect(await body(res)).toEqual(bytes.subarray(start, end + 1));
  });

  it("answers a range past the end with 416 and the size", async () => {
    const id = await recording(true);
    const res = await get(id, owner, { range: "bytes=100000-" });
    expect(res.status).toBe(416);
    expect(res.headers.get("content-range")).toBe("bytes */100000");
    expect(await res.text()).toBe("That part of the recording does not exist.");
  });

  it("names the file for ?download", async () => {
    const id = await recording(true);
    const res = await get(id, owner, {}, "?download");
    expect(res.headers.get("content-disposition")).toBe(`attachment; filename="recording-${id}.mp4"`);
  });

  it("refuses an unfinished recording, a missing file and someone outside the study", async () => {
    const unfinished = await recording(false);
    const early = await get(unfinished, owner);
    expect([early.status, await early.text()]).toEqual([412, "This recording is not finished yet."]);
    const id = await recording(true);
    const refused = await get(id, outsider);
    expect([403, 404]).toContain(refused.status);
    expect(refused.headers.get("content-type")).not.toBe("video/mp4");
    const api = await s.apiAs(owner);
    const { storageKey, sizeBytes } = await api.recordings.media({ recordingId: id });
    expect(sizeBytes).toBe(100_000);
    await s.server.media.storage.remove(storageKey);
    const gone = await get(id, owner);
    expect(gone.status).toBe(404);
    expect(await gone.text()).toBe("This recording's file is missing from media storage.");
  });
});

describe("a recording's chunk route", () => {
  it("keeps a recording whose parts still come from being finished as left behind", async () => {
    const api = await s.apiAs(owner);
    const study = await s.f.newStudy();
    const { version } = await publishedVersion(api, study.id);
    const trial = await api.trials.create({ versionId: version.id });
    const { recordingId } = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
    // Started long ago: only the part that has just come says its recorder is there.
    const longAgo = new Date(Date.now() - 5 * GONE_AFTER_MS);
    await s.db.update(mediaRecordings).set({ createdAt: longAgo }).where(eq(mediaRecordings.id, recordingId));
    const put = await chunks.PUT(
      new Request(`${ORIGIN}/api/recordings/${recordingId}/chunks/3`, {
        method: "PUT",
        headers: { cookie: owner.get("cookie")!, "content-type": "video/mp4" },
        body: bytes.subarray(0, 1000),
      }),
      { params: Promise.resolve({ recordingId, index: "3" }) },
    );
    expect(put.status).toBe(200);
    const row = async () => (await s.db.select().from(mediaRecordings).where(eq(mediaRecordings.id, recordingId)))[0]!;
    expect(await row()).toMatchObject({ chunkCount: 4, lastPartAt: expect.any(Date) });
    expect((await finishLeftOver(s.db, s.server.media)).map((r) => r.id)).not.toContain(recordingId);
    expect((await row()).status).toBe("recording");
  });
});
