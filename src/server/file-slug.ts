// A name as the start of a downloaded file's name: lower case, letters and
// digits joined by hyphens ("Interactive Storyteller" → "interactive-storyteller").
export function fileSlug(name: string, fallback: string): string {
  return (
    name
      .toLowerCase()
      .replace(/[^a-z0-9]+/g, "-")
      .replace(/^-|-$/g, "") || fallback
  );
}
