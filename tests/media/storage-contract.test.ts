// One contract, both media stores: a folder on disk and a real S3-compatible
// server (moto, over a loopback socket) through the `minio` client.
import { afterAll, describe, expect, it } from "vitest";
import { LocalStorage } from "../../src/server/media/local-storage";
import { S3Storage } from "../../src/server/media/s3-storage";
import type { MediaStorage } from "../../src/server/media/storage";
import { startS3Server } from "../support/python";
import { scratchFolder } from "../support/scratch";

const stops: Array<() => void> = [];
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

  it.each(["../escape", "recordings/../../etc/passwd", "/absolute", "a//b", "spaces here", ""])(
    "refuses the key %j and stores nothing",
    async (key) => {
      await expect(store.put(key, new Uint8Array([1]), "video/webm")).rejects.toThrow(/is not a valid media key/);
    },
  );
});
