// A finished recording for the analysis page's player, streamed from media
// storage with byte ranges so the player can seek; with ?download, as a file
// named as the ELAN export links it.
import { byteRange } from "@/core/media/byte-range";
import { apiRoute } from "@/server/api/download";
import { recordingFileName } from "@/server/media/recordings";

export async function GET(req: Request, { params }: { params: Promise<{ recordingId: string }> }) {
  const { recordingId } = await params;
  return apiRoute(req, async (api, context) => {
    const { storageKey, mimeType, sizeBytes } = await api.recordings.media({ recordingId });
    const headers: Record<string, string> = {
      "content-type": mimeType,
      "accept-ranges": "bytes",
      "cache-control": "private, max-age=3600",
    };
    if (new URL(req.url).searchParams.has("download"))
      headers["content-disposition"] = `attachment; filename="${recordingFileName(recordingId, mimeType)}"`;
    const asked = byteRange(req.headers.get("range"), sizeBytes);
    if (asked.kind === "unsatisfiable") {
      return new Response("That part of the recording does not exist.", {
        status: 416,
        headers: { "content-range": `bytes */${sizeBytes}` },
      });
    }
    const range = asked.kind === "part" ? asked.range : undefined;
    const body = await context.media.storage.stream(storageKey, range);
    if (!body) return new Response("This recording's file is missing from media storage.", { status: 404 });
    if (!range) return new Response(body, { headers: { ...headers, "content-length": String(sizeBytes) } });
    return new Response(body, {
      status: 206,
      headers: {
        ...headers,
        "content-range": `bytes ${range.start}-${range.end}/${sizeBytes}`,
        "content-length": String(range.end - range.start + 1),
      },
    });
  });
}
