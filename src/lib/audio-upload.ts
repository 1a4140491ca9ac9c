// Sends a sound file to the study (POST /api/studies/<id>/audio): the bytes
// as they are, the name beside them. The server decides what the file is.
export interface UploadedAudio {
  id: string;
  name: string;
  sha256: string;
  durationMs: number | null;
}

/** The stored file, or an Error with the server's own sentence (too large, not a sound…). */
export async function uploadAudio(studyId: string, file: File): Promise<UploadedAudio> {
  const res = await fetch(`/api/studies/${encodeURIComponent(studyId)}/audio?name=${encodeURIComponent(file.name)}`, {
    method: "POST",
    headers: { "content-type": file.type || "application/octet-stream" },
    body: file,
  });
  if (!res.ok) throw new Error((await res.text()) || `The upload failed (HTTP ${res.status}).`);
  return (await res.json()) as UploadedAudio;
}

/** Where the browser fetches a study's sound to play it. */
export const audioUrl = (audioFileId: string) => `/api/audio/${encodeURIComponent(audioFileId)}`;

/** "1.2 s", "2 min 05 s"; an unknown length says so. */
export function audioLength(ms: number | null): string {
  if (ms === null) return "length unknown";
  const s = ms / 1000;
  if (s < 60) return `${s.toFixed(1)} s`;
  return `${Math.floor(s / 60)} min ${String(Math.round(s % 60)).padStart(2, "0")} s`;
}
