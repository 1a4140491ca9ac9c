// The media store this server uses, chosen once from its configuration.
import { join, resolve } from "node:path";
import type { Config } from "@/store/config";
import { LocalStorage } from "./local-storage";
import { S3Storage } from "./s3-storage";
import type { MediaStorage } from "./storage";

let chosen: MediaStorage | null = null;

export function mediaStorage(config: Config): MediaStorage {
  if (chosen) return chosen;
  if (config.HRI_MEDIA_S3_URL) {
    if (!config.HRI_MEDIA_S3_ACCESS_KEY || !config.HRI_MEDIA_S3_SECRET_KEY) {
      throw new Error("HRI_MEDIA_S3_URL is set: set HRI_MEDIA_S3_ACCESS_KEY and HRI_MEDIA_S3_SECRET_KEY too.");
    }
    chosen = new S3Storage({
      url: config.HRI_MEDIA_S3_URL,
      bucket: config.HRI_MEDIA_S3_BUCKET,
      accessKey: config.HRI_MEDIA_S3_ACCESS_KEY,
      secretKey: config.HRI_MEDIA_S3_SECRET_KEY,
    });
  } else {
    chosen = new LocalStorage(resolve(config.HRI_MEDIA_DIR ?? join(config.HRI_DATA_DIR, "media")));
  }
  return chosen;
}

/** The store and the largest recording it takes, as every server's context carries them. */
export const configuredMedia = (config: Config) => ({
  storage: mediaStorage(config),
  maxBytes: config.HRI_MEDIA_MAX_MB * 1024 * 1024,
});
