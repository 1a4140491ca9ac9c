import type { Database } from "@/store/client";
import { auditLog } from "@/store/schema";

type Tx = Parameters<Parameters<Database["transaction"]>[0]>[0];

/** Records an administrative change in the same transaction as the change. */
export async function audit(
  db: Database | Tx,
  entry: {
    actorId: string | null;
    studyId?: string | null;
    action: string;
    target: string;
    details?: Record<string, unknown>;
  },
) {
  await db.insert(auditLog).values({
    actorId: entry.actorId,
    studyId: entry.studyId ?? null,
    action: entry.action,
    target: entry.target,
    details: entry.details ?? {},
  });
}
