// A stored file streamed as the browser's player asks for it: whole, or the
// one byte range it wants (so it can seek), from media storage.
import { byteRange } from "@/core/media/byte-range";
import type { MediaStorage } from "./storage";

/** `what` names the file ("the recording"); `missing` says that its bytes are gone. */
export async function rangedResponse(
  req: Request,
  storage: MediaStorage,
  file: { storageKey: string; sizeBytes: number; headers: Record<string, string>; what: string; missing: string },
): Promise<Response> {
  const { storageKey, sizeBytes, what } = file;
  const headers = { ...file.headers, "accept-ranges": "bytes" };
  const asked = byteRange(req.headers.get("range"), sizeBytes);
  if (asked.kind === "unsatisfiable") {
    return new Response(`That part of ${what} does not exist.`, {
      status: 416,
      headers: { "content-range": `bytes */${sizeBytes}` },
    });
  }
  const range = asked.kind === "part" ? asked.range : undefined;
  const body = await storage.stream(storageKey, range);
  if (!body) return new Response(file.missing, { status: 404 });
  if (!range) return new Response(body, { headers: { ...headers, "content-length": String(sizeBytes) } });
  return new Response(body, {
    status: 206,
    headers: {
      ...headers,
      "content-range": `bytes ${range.start}-${range.end}/${sizeBytes}`,
      "content-length": String(range.end - range.start + 1),
    },
  });
}
