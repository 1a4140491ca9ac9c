// Adds a sound to the study: the file's bytes as the request body, its name
// in ?name=. The bytes decide what it is (WAV, MP3 or Ogg), never the name
// or the declared type.
import { apiRoute } from "@/server/api/download";
import { readBody } from "@/server/http/body-limit";
import { addAudio, audioName } from "@/server/media/audio";

export async function POST(req: Request, { params }: { params: Promise<{ studyId: string }> }) {
  const { studyId } = await params;
  return apiRoute(req, async (api, context) => {
    const target = await api.audio.uploadTarget({ studyId });
    const name = audioName(new URL(req.url).searchParams.get("name"));
    const bytes = await readBody(req, target.limitBytes, "A sound file");
    if (bytes instanceof Response) return bytes;
    if (bytes.length === 0) return new Response(`“${name}” is empty.`, { status: 400 });
    const added = await addAudio(context.db, context.media.storage, {
      studyId: target.studyId,
      userId: context.user!.id,
      name,
      bytes,
    });
    if (!added.ok) return new Response(added.reason, { status: 415 });
    const { id, sha256, durationMs, mimeType, sizeBytes } = added.audio;
    return Response.json({ id, name, sha256, durationMs, mimeType, sizeBytes }, { status: 201 });
  });
}
