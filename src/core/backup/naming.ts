// The names `npm run backup` gives its files in a folder, and which of them a
// `--keep N` removes. A name carries the time to the millisecond and, when a
// file of that name exists already, a counter: a backup never replaces one.

const PATTERN = /^hristudio-(\d{4}-\d\d-\d\d-\d{6}-\d{3})(?:-(\d+))?\.tar$/;

/** `hristudio-2026-11-26-234712-123.tar`, then `…-123-2.tar`, `…-123-3.tar` for later attempts (from 1). */
export function backupName(now: Date, attempt = 1): string {
  const stamp = now.toISOString().slice(0, 23).replace("T", "-").replaceAll(":", "").replace(".", "-");
  return `hristudio-${stamp}${attempt > 1 ? `-${attempt}` : ""}.tar`;
}

/** Oldest first: by time, then by counter (a name's text alone would put -10 before -2). */
function older(a: string, b: string): number {
  const [, stampA, countA] = PATTERN.exec(a)!;
  const [, stampB, countB] = PATTERN.exec(b)!;
  return stampA! < stampB! ? -1 : stampA! > stampB! ? 1 : Number(countA ?? 1) - Number(countB ?? 1);
}

/**
 * Of the files in a backup folder, the backups beyond the newest `keep` (1 or
 * more), to remove. Only names `backupName` gives count: a file the
 * researcher named, or one still being written (`.part`), is never removed.
 */
export function expiredBackups(files: string[], keep: number): string[] {
  return files
    .filter((f) => PATTERN.test(f))
    .sort(older)
    .slice(0, -keep);
}
