// The kept copies of ended trials' figures (see trialFigures in the schema):
// what the study's tables read instead of folding every log again.
import { sql } from "drizzle-orm";
import { FIGURES_VERSION, type ReportFigures } from "@/core/analysis/trial-figures";
import type { Database } from "./client";
import { trialFigures } from "./schema";

export interface KeptFigures {
  trialId: string;
  versionId: string;
  /** The seq of the last event the figures were folded from. */
  lastSeq: number;
  figures: ReportFigures;
}

/** Whether a kept copy still holds for the trial as it is now. */
export function isCurrent(
  kept: { figuresVersion: number; versionId: string; lastSeq: number } | null,
  trial: { versionId: string; lastSeq: number },
): boolean {
  return (
    kept !== null &&
    kept.figuresVersion === FIGURES_VERSION &&
    kept.versionId === trial.versionId &&
    kept.lastSeq === trial.lastSeq
  );
}

/**
 * Keeps these figures, replacing older copies. A copy folded from fewer
 * events never replaces one folded from more (two readers may fold the same
 * trial at once, one of them before a late event).
 */
export async function keepFigures(db: Database, rows: KeptFigures[]): Promise<void> {
  if (!rows.length) return;
  await db
    .insert(trialFigures)
    .values(rows.map((r) => ({ ...r, figuresVersion: FIGURES_VERSION })))
    .onConflictDoUpdate({
      target: trialFigures.trialId,
      set: {
        figuresVersion: sql`excluded.figures_version`,
        versionId: sql`excluded.version_id`,
        lastSeq: sql`excluded.last_seq`,
        figures: sql`excluded.figures`,
        computedAt: sql`excluded.computed_at`,
      },
      setWhere: sql`${trialFigures.lastSeq} <= excluded.last_seq or ${trialFigures.figuresVersion} <> excluded.figures_version`,
    });
}
