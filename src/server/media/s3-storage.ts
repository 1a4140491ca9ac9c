// Media in MinIO or any S3-compatible server, through the `minio` client.
// The bucket is made on first use.
import { Client } from "minio";
import type { ByteRange } from "@/core/media/byte-range";
import { checkKey, webStream, type MediaStorage } from "./storage";

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

  async put(key: string, data: Uint8Array, contentType: string) {
    await this.bucket();
    await this.client.putObject(this.options.bucket, checkKey(key), Buffer.from(data), data.byteLength, {
      "Content-Type": contentType,
    });
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
