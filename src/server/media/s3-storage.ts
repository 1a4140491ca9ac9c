// Media in MinIO or any S3-compatible server, through the `minio` client.
// The bucket is made on first use.
import { Client } from "minio";
import type { ByteRange } from "@/core/media/byte-range";
import { type Chunks, checkKey, exactly, webStream, type MediaStorage } from "./storage";

/** An upload part: S3 takes at least 5 MB a part (but the last) and at most 10,000 parts. */
const PART_BYTES = 8 * 1024 * 1024;
const MOST_PARTS = 10_000;

/** The chunks gathered into parts of `partSize` (the last shorter), in one buffer reused once a part is taken. */
async function* inParts(chunks: AsyncIterable<Uint8Array>, partSize: number) {
  const part = Buffer.alloc(partSize);
  let held = 0;
  for await (const chunk of chunks)
    for (let at = 0; at < chunk.byteLength; ) {
      const taken = Math.min(partSize - held, chunk.byteLength - at);
      part.set(chunk.subarray(at, at + taken), held);
      held += taken;
      at += taken;
      if (held === partSize) {
        yield part;
        held = 0;
      }
    }
  if (held) yield part.subarray(0, held);
}

const missing = (error: unknown) => ["NoSuchKey", "NotFound"].includes((error as { code?: string }).code ?? "");

export interface S3Options {
  /** e.g. http://127.0.0.1:9000 */
  url: string;
  bucket: string;
  accessKey: string;
  secretKey: string;
  region?: string;
}

export class S3Storage implements MediaStorage {
  private readonly client: Client;
  private bucketReady: Promise<void> | null = null;

  constructor(private readonly options: S3Options) {
    const url = new URL(options.url);
    this.client = new Client({
      endPoint: url.hostname,
      port: url.port ? Number(url.port) : undefined,
      useSSL: url.protocol === "https:",
      accessKey: options.accessKey,
      secretKey: options.secretKey,
      region: options.region ?? "us-east-1",
      pathStyle: true,
    });
  }

  private bucket() {
    this.bucketReady ??= (async () => {
      if (!(await this.client.bucketExists(this.options.bucket)))
        await this.client.makeBucket(this.options.bucket, this.options.region ?? "us-east-1");
    })().catch((error: unknown) => {
      this.bucketReady = null;
      throw error;
    });
    return this.bucketReady;
  }

  put(key: string, data: Uint8Array, contentType: string) {
    return this.putStream(key, [data], data.byteLength, contentType);
  }

  /** One request for what fits a part; a multipart upload, part by part, for more, aborted if the stream fails. */
  async putStream(key: string, data: Chunks, size: number, contentType: string) {
    const name = checkKey(key);
    await this.bucket();
    const partSize = Math.max(PART_BYTES, Math.ceil(size / MOST_PARTS));
    const parts = inParts(exactly(data, size, key), partSize);
    const headers = { "Content-Type": contentType };
    if (size <= partSize) {
      let whole = Buffer.alloc(0);
      for await (const part of parts) whole = Buffer.from(part);
      await this.client.putObject(this.options.bucket, name, whole, size, headers);
      return;
    }
    const uploadID = await this.client.initiateNewMultipartUpload(this.options.bucket, name, headers);
    try {
      const etags: Array<{ part: number; etag: string }> = [];
      for await (const part of parts) {
        const partNumber = etags.length + 1;
        const { etag } = await this.client.uploadPart(
          {
            bucketName: this.options.bucket,
            objectName: name,
            uploadID,
            partNumber,
            headers: { "Content-Length": part.length },
          },
          part,
        );
        etags.push({ part: partNumber, etag });
      }
      await this.client.completeMultipartUpload(this.options.bucket, name, uploadID, etags);
    } catch (error) {
      // Its parts would stay in the bucket, unseen but kept.
      await this.client.abortMultipartUpload(this.options.bucket, name, uploadID).catch(() => {});
      throw error;
    }
  }

  async get(key: string) {
    await this.bucket();
    try {
      const stream = await this.client.getObject(this.options.bucket, checkKey(key));
      const chunks: Buffer[] = [];
      for await (const chunk of stream) chunks.push(chunk as Buffer);
      return Buffer.concat(chunks);
    } catch (error) {
      if (missing(error)) return null;
      throw error;
    }
  }

  async size(key: string) {
    await this.bucket();
    try {
      return (await this.client.statObject(this.options.bucket, checkKey(key))).size;
    } catch (error) {
      if (missing(error)) return null;
      throw error;
    }
  }

  async stream(key: string, range?: ByteRange) {
    await this.bucket();
    try {
      const body = range
        ? await this.client.getPartialObject(
            this.options.bucket,
            checkKey(key),
            range.start,
            range.end - range.start + 1,
          )
        : await this.client.getObject(this.options.bucket, checkKey(key));
      return webStream(body);
    } catch (error) {
      if (missing(error)) return null;
      throw error;
    }
  }

  async list(prefix: string) {
    await this.bucket();
    const keys: string[] = [];
    for await (const item of this.client.listObjectsV2(this.options.bucket, prefix, true))
      if ((item as { name?: string }).name) keys.push((item as { name: string }).name);
    return keys.sort();
  }

  async remove(key: string) {
    await this.bucket();
    await this.client.removeObject(this.options.bucket, checkKey(key));
  }
}
