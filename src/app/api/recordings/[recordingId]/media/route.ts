// A finished recording for the analysis page's player, with byte ranges so
// the player can seek; with ?download, as a file named as the ELAN export links it.
import { apiRoute } from "@/server/api/download";
import { recordingFileName } from "@/server/media/recordings";

export async function GET(req: Request, { params }: { params: Promise<{ recordingId: string }> }) {
  const { recordingId } = await params;
  return apiRoute(req, async (api) => {
    const { bytes, mimeType } = await api.recordings.file({ recordingId });
    const range = /^bytes=(\d*)-(\d*)$/.exec(req.headers.get("range") ?? "");
    const headers: Record<string, string> = { "content-type": mimeType, "accept-ranges": "bytes", "cache-control": "private, max-age=3600" };
    if (new URL(req.url).searchParams.has("download")) headers["content-disposition"] = `attachment; filename="${recordingFileName(recordingId, mimeType)}"`;
    if (!range || (!range[1] && !range[2])) return new Response(new Uint8Array(bytes), { headers: { ...headers, "content-length": String(bytes.length) } });
    const start = range[1] ? Number(range[1]) : Math.max(0, bytes.length - Number(range[2]));
    const end = range[1] && range[2] ? Math.min(Number(range[2]), bytes.length - 1) : bytes.length - 1;
    if (start > end || start >= bytes.length) return new Response("That part of the recording does not exist.", { status: 416, headers: { "content-range": `bytes */${bytes.length}` } });
    return new Response(new Uint8Array(bytes.subarray(start, end + 1)), {
      status: 206,
      headers: { ...headers, "content-range": `bytes ${start}-${end}/${bytes.length}`, "content-length": String(end - start + 1) },
    });
  });
}
