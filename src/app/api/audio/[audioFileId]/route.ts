// One of a study's sounds, for the wizard's browser that plays a "Play audio"
// action and the designer's preview: streamed from media storage in ranges.
import { apiRoute } from "@/server/api/download";
import { rangedResponse } from "@/server/media/ranged";

export async function GET(req: Request, { params }: { params: Promise<{ audioFileId: string }> }) {
  const { audioFileId } = await params;
  return apiRoute(req, async (api, context) => {
    const { storageKey, mimeType, sizeBytes, name } = await api.audio.media({ audioFileId });
    // The file under an id never changes: a new sound is a new file.
    const headers = { "content-type": mimeType, "cache-control": "private, max-age=86400, immutable" };
    return rangedResponse(req, context.media.storage, {
      storageKey,
      sizeBytes,
      headers,
      what: `the sound “${name}”`,
      missing: `The sound “${name}” is missing from media storage.`,
    });
  });
}
