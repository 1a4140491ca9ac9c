// Request bodies are limited while they are read, not after: a body with no
// declared length that never ends is cut off shortly after the limit (the
// route stops pulling from it), answered 413 with the limit named, and
// nothing of it is stored. Each route holds its own limit.
import { afterAll, describe, expect, it } from "vitest";
import { CHUNK_LIMIT_BYTES } from "../../src/server/media/recordings";
import { LIMITS } from "../../src/core/network/limits";
import { endlessBody, ORIGIN, routeServer } from "../support/routes";
import { publishedVersion } from "./fixture";

const s = await routeServer();
afterAll(s.close);
const chunks = await import("../../src/app/api/recordings/[recordingId]/chunks/[index]/route");
const trpc = await import("../../src/app/api/trpc/[trpc]/route");
const auth = await import("../../src/app/api/auth/[...all]/route");
const owner = await s.signIn("owner");
const PIECE = 64 * 1024;

async function recording() {
  const api = await s.apiAs(owner);
  const study = await s.f.newStudy();
  const { version } = await publishedVersion(api, study.id);
  const trial = await api.trials.create({ versionId: version.id });
  return (await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/webm" })).recordingId;
}

const put = (recordingId: string, body: BodyInit, headers: Record<string, string> = {}) =>
  chunks.PUT(
    new Request(`${ORIGIN}/api/recordings/${recordingId}/chunks/0`, {
      method: "PUT",
      headers: { cookie: owner.get("cookie")!, "content-type": "video/webm", ...headers },
      body,
      duplex: "half",
    } as RequestInit),
    {
      params: Promise.resolve({ recordingId, index: "0" }),
    },
  );

describe("a recording part", () => {
  it("is cut off while it streams in: 413 soon after the limit, the rest never pulled, nothing stored", async () => {
    const recordingId = await recording();
    const { body, counted } = endlessBody(PIECE);
    const res = await put(recordingId, body);
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A part of a recording may be at most 16 MB; this one is larger.");
    expect(counted.pulled).toBeGreaterThan(CHUNK_LIMIT_BYTES);
    expect(counted.pulled).toBeLessThanOrEqual(CHUNK_LIMIT_BYTES + 2 * PIECE);
    expect(counted.cancelled).toBe(true);
    expect(await s.server.media.storage.list(`recordings/${recordingId}/`)).toEqual([]);
  });

  it("is refused before a byte is read when its declared length is over the limit", async () => {
    const recordingId = await recording();
    const { body, counted } = endlessBody(PIECE);
    const res = await put(recordingId, body, { "content-length": String(20 * 1024 * 1024) });
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A part of a recording may be at most 16 MB; this one is 20 MB.");
    expect(counted.pulled).toBe(0);
  });

  it("within the limit is stored", async () => {
    const recordingId = await recording();
    const res = await put(recordingId, new Uint8Array(3 * PIECE).fill(7));
    expect(await res.json()).toEqual({ stored: 0, bytes: 3 * PIECE });
    expect((await s.server.media.storage.get(`recordings/${recordingId}/chunk-000000`))!.length).toBe(3 * PIECE);
  });
});

const trpcPost = (path: string, body: BodyInit, headers: Record<string, string> = {}) =>
  trpc.POST(
    new Request(`${ORIGIN}/api/trpc/${path}`, {
      method: "POST",
      headers: { "content-type": "application/json", ...headers },
      body,
      duplex: "half",
    } as RequestInit),
  );

describe("the API", () => {
  it("holds the public form to its small limit while reading, for someone not signed in", async () => {
    const { body, counted } = endlessBody(PIECE);
    const res = await trpcPost("form.save", body);
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A request to the public form may be at most 512 KB; this one is larger.");
    expect(counted.pulled).toBeLessThanOrEqual(LIMITS.publicApi + 2 * PIECE);
    expect(counted.cancelled).toBe(true);
  });

  it("holds anyone not signed in to the same limit on every procedure", async () => {
    const { body, counted } = endlessBody(PIECE);
    const res = await trpcPost("studies.create", body);
    expect(res.status).toBe(413);
    expect(counted.pulled).toBeLessThanOrEqual(LIMITS.publicApi + 2 * PIECE);
  });

  it("lets a signed-in researcher send more (an experiment file), up to the API's limit", async () => {
    const study = await s.f.newStudy();
    const text = JSON.stringify({ padding: "x".repeat(1024 * 1024) });
    // Read and parsed: the answer is about the file, not its size.
    const fits = await trpcPost("experiments.importFile", JSON.stringify({ studyId: study.id, text }), {
      cookie: owner.get("cookie")!,
    });
    expect(fits.status).toBe(400);
    expect((await fits.json()).error.message).not.toMatch(/at most/);
    const { body, counted } = endlessBody(PIECE);
    const res = await trpcPost("experiments.importFile", body, { cookie: owner.get("cookie")! });
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A request to the API may be at most 8 MB; this one is larger.");
    expect(counted.pulled).toBeLessThanOrEqual(LIMITS.api + 2 * PIECE);
  });

  it("refuses a batch of more calls than the browser's client ever sends", async () => {
    const paths = Array.from({ length: LIMITS.batchCalls + 1 }, () => "studies.mine").join(",");
    const res = await trpc.GET(
      new Request(`${ORIGIN}/api/trpc/${paths}?batch=1&input={}`, { headers: { cookie: owner.get("cookie")! } }),
    );
    expect(res.status).toBe(400);
    expect(JSON.stringify(await res.json())).toContain("Batch call exceeds maximum size");
    const within = Array.from({ length: LIMITS.batchCalls }, () => "studies.mine").join(",");
    expect(
      (
        await trpc.GET(
          new Request(`${ORIGIN}/api/trpc/${within}?batch=1&input={}`, { headers: { cookie: owner.get("cookie")! } }),
        )
      ).status,
    ).toBe(200);
  });
});

describe("sign-in", () => {
  it("is cut off at its limit while reading", async () => {
    const { body, counted } = endlessBody(PIECE);
    const res = await auth.POST(
      new Request(`${ORIGIN}/api/auth/sign-in/email`, {
        method: "POST",
        headers: { "content-type": "application/json", origin: ORIGIN },
        body,
        duplex: "half",
      } as RequestInit),
    );
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A sign-in request may be at most 64 KB; this one is larger.");
    expect(counted.pulled).toBeLessThanOrEqual(LIMITS.auth + 2 * PIECE);
  });
});
