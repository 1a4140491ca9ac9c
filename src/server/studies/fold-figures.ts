// Ended trials' figures folded from their logs, then kept
// (src/store/trial-figures.ts) so the next read of the Results tab takes them
// as they are. A fold under way in this process is shared: the Results tab
// asks for the figures and the results by condition at once, and each trial's
// log is read and folded once for both.
import { inArray } from "drizzle-orm";
import { fidelityReport } from "@/core/analysis/fidelity";
import { type ReportFigures, reportFigures } from "@/core/analysis/trial-figures";
import type { Database } from "@/store/client";
import { logUnexpected } from "@/store/error-reference";
import { foldableEventsOfTrials } from "@/store/event-store";
import { experimentVersions } from "@/store/schema";
import { type KeptFigures, keepFigures } from "@/store/trial-figures";

/** A hundred trials' events are read in one query, folded, and let go before the next hundred are read. */
const FOLD_BATCH = 100;

/** A trial whose figures are not kept, or not for its log as it is now. */
export interface TrialToFold {
  id: string;
  versionId: string;
  lastSeq: number;
}

/** Folds under way, by what they fold: the trial, its protocol version and its log's last seq. */
const underWay = new Map<string, Promise<ReportFigures>>();
const keyOf = (t: TrialToFold) => `${t.id}:${t.versionId}:${t.lastSeq}`;

/** These trials' figures, by trial: folded a batch at a time (one batch's events held at once), and kept. */
export async function foldFigures(db: Database, trials: TrialToFold[]): Promise<Map<string, ReportFigures>> {
  const mine = trials.filter((t) => !underWay.has(keyOf(t)));
  const protocols = mine.length ? protocolsOf(db, mine) : null;
  let previous: Promise<unknown> = Promise.resolve();
  for (let start = 0; start < mine.length; start += FOLD_BATCH) {
    const batch = mine.slice(start, start + FOLD_BATCH);
    const folded = previous.then(async () => foldBatch(db, batch, await protocols!));
    previous = folded;
    for (const t of batch)
      underWay.set(
        keyOf(t),
        folded.then((figures) => figures.get(t.id)!),
      );
    const settled = () => batch.forEach((t) => underWay.delete(keyOf(t)));
    folded.then(settled, settled);
  }
  // Taken before anything settles (no await above), so each is this call's fold or another's still under way.
  const waiting = trials.map((t) => [t.id, underWay.get(keyOf(t))!] as const);
  return new Map(await Promise.all(waiting.map(async ([id, figures]) => [id, await figures] as const)));
}

async function protocolsOf(db: Database, trials: TrialToFold[]) {
  const rows = await db
    .select({ id: experimentVersions.id, snapshot: experimentVersions.snapshot })
    .from(experimentVersions)
    .where(inArray(experimentVersions.id, [...new Set(trials.map((t) => t.versionId))]));
  return new Map(rows.map((v) => [v.id, v.snapshot]));
}

async function foldBatch(
  db: Database,
  batch: TrialToFold[],
  protocols: Awaited<ReturnType<typeof protocolsOf>>,
): Promise<Map<string, ReportFigures>> {
  const events = await foldableEventsOfTrials(
    db,
    batch.map((t) => t.id),
  );
  const folded: KeptFigures[] = batch.map(({ id, versionId }) => {
    const log = events.get(id)!;
    return {
      trialId: id,
      versionId,
      // The last event folded, not the one seen before reading: an event appended meanwhile leaves the copy stale.
      lastSeq: log.at(-1)?.seq ?? 0,
      figures: reportFigures(fidelityReport(protocols.get(versionId)!, log)),
    };
  });
  // The figures stand whether or not they could be kept (a trial deleted meanwhile): the next read folds again.
  await keepFigures(db, folded).catch((error) => logUnexpected(error, "keeping trials' figures"));
  return new Map(folded.map((f) => [f.trialId, f.figures]));
}
