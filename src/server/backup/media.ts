// Every object of the media store (finished recordings, and the parts of
// ones still being recorded) into the backup file, and back.
import { addAbortSignal } from "node:stream";
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

/**
 * Each media file streamed from the backup into the store, a chunk at a time
 * (a recording of any length takes a chunk's memory). `written` hears each
 * file once it is stored, so a restore that stops can remove them.
 */
export async function restoreMedia(
  storage: MediaStorage,
  reader: BackupReader,
  media: BackupManifest["media"],
  progress: (line: string) => void,
  written: string[],
  signal: AbortSignal,
) {
  for (const [i, { key }] of media.entries()) {
    signal.throwIfAborted();
    progress(`media files ${i + 1}/${media.length} (${key})`);
    const file = mediaFile(key);
    try {
      await storage.putStream(key, addAbortSignal(signal, reader.stream(file)), reader.size(file), contentType(key));
    } catch (error) {
      signal.throwIfAborted();
      throw new Error(
        `Could not restore the media file ${key}: ${error instanceof Error ? error.message : String(error)}`,
      );
    }
    written.push(key);
  }
}
