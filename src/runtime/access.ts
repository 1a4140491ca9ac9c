// The database side of the socket's access checks: what the runtime reads at
// hello and whenever PostgreSQL announces a change, never on each command.
import { and, eq, isNull, lt, or } from "drizzle-orm";
import type postgres from "postgres";
import type { AccessChange, TrialAccess } from "@/core/access/trial-socket";
import type { Database } from "@/store/client";
import { mediaRecordings, socketTokenUses, trials, user } from "@/store/schema";
import { studyAccessOf } from "@/store/study-access";
import type { SocketClaims } from "@/store/socket-token";

/** The caller's access to a trial now; null when the trial no longer exists. */
export async function loadTrialAccess(db: Database, trialId: string, userId: string): Promise<TrialAccess | null> {
  const [trial] = await db
    .select({
      studyId: trials.studyId,
      wizardId: trials.wizardId,
      status: trials.status,
      isRehearsal: trials.isRehearsal,
    })
    .from(trials)
    .where(eq(trials.id, trialId));
  if (!trial) return null;
  const [[person], study] = await Promise.all([
    db.select({ name: user.name, role: user.role, disabled: user.disabled }).from(user).where(eq(user.id, userId)),
    studyAccessOf(db, trial.studyId, userId),
  ]);
  return {
    userId,
    name: person?.name ?? "",
    systemRole: person?.role ?? "observer",
    active: person !== undefined && !person.disabled,
    studyId: trial.studyId,
    studyRole: study.role,
    studyStatus: study.status,
    blinding: study.blinding,
    trial: { wizardId: trial.wizardId, status: trial.status, isRehearsal: trial.isRehearsal },
  };
}

/** Records the token as used; false when it was used before (each works once). */
export async function spendToken(db: Database, claims: SocketClaims): Promise<boolean> {
  const rows = await db
    .insert(socketTokenUses)
    .values({
      tokenId: claims.tokenId,
      userId: claims.userId,
      trialId: claims.trialId,
      expiresAt: new Date(claims.exp),
    })
    .onConflictDoNothing()
    .returning({ tokenId: socketTokenUses.tokenId });
  return rows.length === 1;
}

/** Forgets used tokens past their expiry: an expired token is refused anyway. */
export async function purgeSpentTokens(db: Database): Promise<void> {
  await db.delete(socketTokenUses).where(lt(socketTokenUses.expiresAt, new Date()));
}

/** Makes the wizard the trial's wizard unless someone else claimed it first. */
export async function claimTrial(db: Database, trialId: string, userId: string): Promise<boolean> {
  const rows = await db
    .update(trials)
    .set({ wizardId: userId })
    .where(and(eq(trials.id, trialId), or(isNull(trials.wizardId), eq(trials.wizardId, userId))))
    .returning({ id: trials.id });
  return rows.length === 1;
}

/** A recording is logged only on its own trial. */
export async function isRecordingOf(db: Database, recordingId: string, trialId: string): Promise<boolean> {
  const rows = await db
    .select({ id: mediaRecordings.id })
    .from(mediaRecordings)
    .where(and(eq(mediaRecordings.id, recordingId), eq(mediaRecordings.trialId, trialId)));
  return rows.length === 1;
}

export const ACCESS_CHANNEL = "hri_access";

/**
 * Follows the database's announcements of who may do what (triggers on
 * members, studies, trials' wizard and accounts). `resync` runs each time the
 * listening connection is (re)established: anything announced while it was
 * down is caught by checking every open socket again.
 */
export async function watchAccess(sql: postgres.Sql, changed: (change: AccessChange) => void, resync: () => void) {
  const listener = await sql.listen(
    ACCESS_CHANNEL,
    (payload) => {
      try {
        changed(JSON.parse(payload) as AccessChange);
      } catch {
        resync();
      }
    },
    resync,
  );
  return { close: () => listener.unlisten() };
}
