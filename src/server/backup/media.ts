// Every object of the media store (finished recordings, and the parts of
// ones still being recorded) into the backup file, and back.
import { mediaFile, type BackupManifest } from "@/core/backup/manifest";
import type { MediaStorage } from "../media/storage";
import type { BackupWriter } from "./archive";
import type { BackupReader } from "./archive-reader";

const CONTENT_TYPES: Record<string, string> = { webm: "video/webm", mp4: "video/mp4", ogg: "audio/ogg" };
const contentType = (key: string) => CONTENT_TYPES[key.slice(key.lastIndexOf(".") + 1)] ?? "application/octet-stream";

export async function dumpMedia(
  storage: MediaStorage,
  writer: BackupWriter,
  progress: (line: string) => void,
): Promise<BackupManifest["media"]> {
  const keys = await storage.list("");
  const media: BackupManifest["media"] = [];
  for (const [i, key] of keys.entries()) {
    progress(`media files ${i + 1}/${keys.length} (${key})`);
    const stream = await storage.stream(key);
    if (!stream) continue; // Removed since the listing (a recording's parts, once joined).
    media.push({ key, size: await writer.add(mediaFile(key), stream as unknown as AsyncIterable<Uint8Array>) });
  }
  return media;
}

export async function restoreMedia(
  storage: MediaStorage,
  reader: BackupReader,
  media: BackupManifest["media"],
  progress: (line: string) => void,
) {
  // One buffer, as large as the largest recording, for them all: memory does not follow their number.
  const buffer = new Uint8Array(media.reduce((most, m) => Math.max(most, reader.size(mediaFile(m.key))), 0));
  for (const [i, { key }] of media.entries()) {
    progress(`media files ${i + 1}/${media.length} (${key})`);
    await storage.put(key, await reader.readInto(mediaFile(key), buffer), contentType(key));
  }
}
