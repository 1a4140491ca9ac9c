// Where tests write files: one folder of the run's own under .tmp (ignored by
// git), which the run removes when it ends (global-setup.ts), so a run leaves
// nothing behind however many apps, databases and files its tests made.
// Outside vitest (the benchmarks) it is .tmp itself.
import { mkdirSync, mkdtempSync } from "node:fs";
import { join, resolve } from "node:path";

const root = resolve(import.meta.dirname, "..", "..");

/** Set by the run's global setup; its workers inherit it. */
export const SCRATCH_VARIABLE = "HRI_TEST_SCRATCH";

export function scratchRoot(): string {
  const dir = process.env[SCRATCH_VARIABLE] || join(root, ".tmp");
  mkdirSync(dir, { recursive: true });
  return dir;
}

/** A new empty folder, named from `prefix`, removed with the run's folder. */
export function scratchFolder(prefix: string): string {
  return mkdtempSync(join(scratchRoot(), prefix));
}
