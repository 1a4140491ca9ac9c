// The study-level figures: every finished, non-rehearsal trial of a
// participant who has not withdrawn, folded into its fidelity report.
import { and, asc, eq, inArray, ne } from "drizzle-orm";
import { fidelityReport } from "@/core/analysis/fidelity";
import { studySummary } from "@/core/analysis/study-summary";
import type { TrialEvent } from "@/core/trial";
import type { Database } from "@/store/client";
import { conditions, experimentVersions, participants, trials } from "@/store/schema";
import { eventsSince } from "@/store/event-store";

export async function studyFigures(db: Database, studyId: string) {
  const rows = await db
    .select({
      id: trials.id,
      code: participants.code,
      condition: conditions.name,
      protocol: experimentVersions.snapshot,
    })
    .from(trials)
    .innerJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(conditions, eq(conditions.id, participants.conditionId))
    .where(
      and(
        eq(trials.studyId, studyId),
        eq(trials.isRehearsal, false),
        ne(participants.consentStatus, "withdrawn"),
        inArray(trials.status, ["completed", "aborted"]),
      ),
    )
    .orderBy(asc(trials.createdAt));
  const figures = await Promise.all(
    rows.map(async (r) => ({
      trialId: r.id,
      participantCode: r.code,
      condition: r.condition,
      report: fidelityReport(r.protocol, (await eventsSince(db, r.id)) as unknown as TrialEvent[]),
    })),
  );
  return studySummary(figures);
}
