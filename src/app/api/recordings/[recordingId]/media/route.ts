// A finished recording for the analysis page's player, streamed from media
// storage with byte ranges so the player can seek; with ?download, as a file
// named as the ELAN export links it.
import { apiRoute } from "@/server/api/download";
import { rangedResponse } from "@/server/media/ranged";
import { recordingFileName } from "@/server/media/recordings";

export async function GET(req: Request, { params }: { params: Promise<{ recordingId: string }> }) {
  const { recordingId } = await params;
  return apiRoute(req, async (api, context) => {
    const { storageKey, mimeType, sizeBytes } = await api.recordings.media({ recordingId });
    const headers: Record<string, string> = { "content-type": mimeType, "cache-control": "private, max-age=3600" };
    if (new URL(req.url).searchParams.has("download"))
      headers["content-disposition"] = `attachment; filename="${recordingFileName(recordingId, mimeType)}"`;
    return rangedResponse(req, context.media.storage, {
      storageKey,
      sizeBytes,
      headers,
      what: "the recording",
      missing: "This recording's file is missing from media storage.",
    });
  });
}
