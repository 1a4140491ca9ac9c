// One part of a recording, stored as it arrives. Sending a part again
// replaces it, so a recorder that lost its connection simply resends.
import { apiRoute } from "@/server/api/download";
import { readBody } from "@/server/http/body-limit";
import { chunkKey, CHUNK_LIMIT_BYTES, partArrived } from "@/server/media/recordings";

const refuse = (status: number, message: string) => new Response(message, { status });
const baseType = (type: string | null) => (type ?? "").split(";")[0]!.trim();

export async function PUT(req: Request, { params }: { params: Promise<{ recordingId: string; index: string }> }) {
  const { recordingId, index } = await params;
  return apiRoute(req, async (api, context) => {
    const target = await api.recordings.chunkTarget({ recordingId });
    const n = Number(index);
    if (!/^\d{1,6}$/.test(index))
      return refuse(400, `The part number "${index.slice(0, 20)}" is not a whole number from 0 to 999999.`);
    if (baseType(req.headers.get("content-type")) !== baseType(target.mimeType)) {
      return refuse(
        415,
        `This recording is ${baseType(target.mimeType)}; a part sent as "${baseType(req.headers.get("content-type")) || "no type"}" is refused.`,
      );
    }
    const body = await readBody(req, CHUNK_LIMIT_BYTES, "A part of a recording");
    if (body instanceof Response) return body;
    if (body.length === 0) return refuse(400, "This part of the recording is empty.");
    await context.media.storage.put(chunkKey(target.storageKey, n), body, target.mimeType);
    await partArrived(context.db, recordingId, n);
    return Response.json({ stored: n, bytes: body.length });
  });
}
