// One contract, both media stores: a folder on disk and a real S3-compatible
// server (moto, over a loopback socket) through the `minio` client.
import { createHash } from "node:crypto";
import { afterAll, describe, expect, it } from "vitest";
import { LocalStorage } from "../../src/server/media/local-storage";
import { S3Storage } from "../../src/server/media/s3-storage";
import type { MediaStorage } from "../../src/server/media/storage";
import { liveBuffers } from "../support/memory";
import { startS3Server } from "../support/python";
import { scratchFolder } from "../support/scratch";

const stops: Array<() => void> = [];

const MB = 1024 * 1024;

/** `size` bytes in chunks of 256 KB, each made when pulled; `pulled` hears how far it has been read. */
async function* generated(size: number, pulled: (at: number) => void = () => {}, failAt = Number.POSITIVE_INFINITY) {
  for (let at = 0; at < size; at += 256 * 1024) {
    if (at >= failAt) throw new Error("The camera's disk went away.");
    pulled(at);
    yield new Uint8Array(Math.min(256 * 1024, size - at)).map((_, i) => ((at + i) * 13 + (at >> 20)) % 256);
  }
}

const sha256 = async (chunks: AsyncIterable<Uint8Array>) => {
  const hash = createHash("sha256");
  for await (const chunk of chunks) hash.update(chunk);
  return hash.digest("hex");
};
afterAll(() => stops.forEach((stop) => stop()));

async function local(): Promise<MediaStorage> {
  return new LocalStorage(scratchFolder("media-"));
}

async function s3(): Promise<MediaStorage> {
  const server = await startS3Server();
  stops.push(server.stop);
  return new S3Storage({ url: server.url, bucket: "hristudio-test", accessKey: "test", secretKey: "test-secret" });
}

describe.each([
  ["a local folder", local],
  ["an S3-compatible server", s3],
])("media storage in %s", (_name, make) => {
  let store: MediaStorage;

  it("gives back exactly the bytes it was given, binary and large", async () => {
    store = await make();
    const bytes = new Uint8Array(6 * 1024 * 1024 + 7).map((_, i) => (i * 31) % 256);
    await store.put("recordings/r1/chunk-000001", bytes, "video/webm");
    expect(Buffer.compare((await store.get("recordings/r1/chunk-000001"))!, Buffer.from(bytes))).toBe(0);
  }, 120_000);

  it("replaces on a second put, and lists a prefix in order", async () => {
    await store.put("recordings/r1/chunk-000002", new Uint8Array([1]), "video/webm");
    await store.put("recordings/r1/chunk-000002", new Uint8Array([2, 2]), "video/webm");
    await store.put("recordings/r10/chunk-000001", new Uint8Array([9]), "video/webm");
    expect([...(await store.get("recordings/r1/chunk-000002"))!]).toEqual([2, 2]);
    expect(await store.list("recordings/r1/")).toEqual(["recordings/r1/chunk-000001", "recordings/r1/chunk-000002"]);
  });

  it("tells the size, and streams the whole or a range of bytes", async () => {
    const bytes = (await store.get("recordings/r1/chunk-000001"))!;
    expect(await store.size("recordings/r1/chunk-000001")).toBe(bytes.length);
    const read = async (stream: ReadableStream<Uint8Array> | null) =>
      Buffer.from(await new Response(stream).arrayBuffer());
    expect(Buffer.compare(await read(await store.stream("recordings/r1/chunk-000001")), bytes)).toBe(0);
    const middle = await read(await store.stream("recordings/r1/chunk-000001", { start: 1_000_000, end: 1_000_009 }));
    expect([...middle]).toEqual([...bytes.subarray(1_000_000, 1_000_010)]);
    const last = await read(
      await store.stream("recordings/r1/chunk-000001", { start: bytes.length - 1, end: bytes.length - 1 }),
    );
    expect([...last]).toEqual([bytes.at(-1)]);
    expect(await store.size("recordings/none/chunk-000001")).toBeNull();
    expect(await store.stream("recordings/none/chunk-000001")).toBeNull();
  }, 60_000);

  it("answers null for what it does not hold, and removes", async () => {
    expect(await store.get("recordings/none/chunk-000001")).toBeNull();
    await store.remove("recordings/r1/chunk-000002");
    expect(await store.get("recordings/r1/chunk-000002")).toBeNull();
    expect(await store.list("recordings/nothing-here/")).toEqual([]);
  });

  it("stores a stream of many MB as it is pulled, never holding much of it", async () => {
    const size = 40 * MB + 3;
    const before = liveBuffers();
    let held = 0;
    await store.putStream(
      "recordings/long.webm",
      generated(size, (at) => {
        if (at % (2 * MB) === 0) held = Math.max(held, liveBuffers() - before);
      }),
      size,
      "video/webm",
    );
    expect(await store.size("recordings/long.webm")).toBe(size);
    const stored = await store.stream("recordings/long.webm");
    expect(await sha256(stored as unknown as AsyncIterable<Uint8Array>)).toBe(await sha256(generated(size)));
    // A chunk, or one upload part of 8 MB: far from the 40 MB a store holding the stream would need.
    expect(held).toBeLessThan(20 * MB);
  }, 180_000);

  it("leaves what was under the key as it was when the stream fails half way", async () => {
    await store.put("recordings/kept.webm", new Uint8Array([7, 7]), "video/webm");
    await expect(
      store.putStream("recordings/kept.webm", generated(20 * MB, undefined, 10 * MB), 20 * MB, "video/webm"),
    ).rejects.toThrow("The camera's disk went away.");
    await expect(
      store.putStream("recordings/new.webm", generated(MB, undefined, MB / 2), MB, "video/webm"),
    ).rejects.toThrow("The camera's disk went away.");
    expect([...(await store.get("recordings/kept.webm"))!]).toEqual([7, 7]);
    expect(await store.get("recordings/new.webm")).toBeNull();
    expect(await store.list("recordings/")).not.toContain("recordings/new.webm");
  }, 120_000);

  it.each([
    ["fewer", 4],
    ["more", 2],
  ])("refuses a stream of %s bytes than it was said to hold, storing nothing", async (word, size) => {
    await expect(
      store.putStream("recordings/odd.webm", [new Uint8Array([1, 2, 3])], size, "video/webm"),
    ).rejects.toThrow(`The bytes for the media file "recordings/odd.webm" were ${word} than the ${size} expected.`);
    expect(await store.get("recordings/odd.webm")).toBeNull();
  });

  it.each(["../escape", "recordings/../../etc/passwd", "/absolute", "a//b", "spaces here", ""])(
    "refuses the key %j and stores nothing",
    async (key) => {
      await expect(store.put(key, new Uint8Array([1]), "video/webm")).rejects.toThrow(/is not a valid media key/);
    },
  );
});
