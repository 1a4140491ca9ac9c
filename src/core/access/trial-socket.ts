// Who may do what on a trial's socket. Pure: the runtime keeps each open
// socket's access fresh from the database (at hello, then on every change
// PostgreSQL announces) and asks here on every message, so a decision never
// waits on the database and never rests on what the client claims.
import type { Blinding } from "../studies/blinding";
import { type StudyStatus, trialRefusal } from "../studies/status";
import type { TrialState } from "../trial/types";
import { decide, runsAssigned, studyRoleMay, type StudyRole, type SystemRole } from "./policy";

export interface TrialAccess {
  userId: string;
  name: string;
  systemRole: SystemRole;
  /** False once the account is disabled or deleted. */
  active: boolean;
  studyId: string;
  /** The caller's role in the trial's study; null once they are no longer a member. */
  studyRole: StudyRole | null;
  /** Only an active study starts trials with participants (a draft rehearses). */
  studyStatus: StudyStatus;
  blinding: Blinding;
  trial: { wizardId: string | null; status: TrialState["status"]; isRehearsal: boolean };
}

export type SocketVerdict = { allow: true; claim: boolean } | { allow: false; reason: string };

const refuse = (reason: string): SocketVerdict => ({ allow: false, reason });

/** Why this socket must close now, or null while its user may stay. */
export function lostAccess(access: TrialAccess): string | null {
  if (!access.active) return "Your account is no longer active.";
  if (access.studyRole === null) return "You are no longer a member of this study.";
  return null;
}

/** May the caller send this command (a kind from the socket messages) to the trial? */
export function commandVerdict(access: TrialAccess, kind: string): SocketVerdict {
  const lost = lostAccess(access);
  if (lost) return refuse(lost);
  const role = access.studyRole!;
  if (!studyRoleMay(role, "trial.run")) return refuse(`As ${role} you may watch this trial but not run it.`);
  // Safety before procedure: whoever may run trials in this study may stop the
  // robot of any of them, the trial's own wizard or not.
  if (kind === "emergency_stop") return { allow: true, claim: false };
  // A trial made while the study was active does not start once it is a draft again, or completed;
  // one already running carries on, so no participant is left mid-protocol.
  const notNow = kind === "start" && !access.trial.isRehearsal ? trialRefusal(access.studyStatus) : null;
  if (notNow) return refuse(notNow);
  // Whoever starts an unassigned trial runs it: starting records them as its
  // wizard, so the trial is credited to who ran it, not to who created it.
  if (access.trial.wizardId === null) return { allow: true, claim: kind === "start" };
  if (runsAssigned(role, access.trial.wizardId, access.userId)) return { allow: true, claim: false };
  return refuse("This trial is assigned to another wizard: you may watch it but not run it.");
}

/** May the caller annotate in this trial? */
export function annotateVerdict(access: TrialAccess): SocketVerdict {
  const lost = lostAccess(access);
  if (lost) return refuse(lost);
  return studyRoleMay(access.studyRole!, "annotation.create")
    ? { allow: true, claim: false }
    : refuse(`As ${access.studyRole} you may not annotate in this trial.`);
}

/**
 * May the caller code this trial live, with a key per code? Whoever may
 * annotate, while the trial runs: codes are timed from its start, and a
 * finished trial is coded on its analysis page, against the recording.
 */
export function codeVerdict(access: TrialAccess): SocketVerdict {
  const lost = lostAccess(access);
  if (lost) return refuse(lost);
  if (!studyRoleMay(access.studyRole!, "annotation.create"))
    return refuse(`As ${access.studyRole} you may not code in this trial.`);
  if (access.trial.status === "scheduled")
    return refuse("The trial has not started yet: codes are timed from its start.");
  if (access.trial.status === "completed" || access.trial.status === "aborted")
    return refuse("The trial has ended: code it on its analysis page, against the recording.");
  return { allow: true, claim: false };
}

/**
 * May the caller receive the trial's event log? Whoever may read the study's
 * data (blinds included); and any member while the trial is live, since
 * watching it unfold is what the socket is for. A finished trial's log is results.
 */
export function mayReadTrialLog(access: TrialAccess): boolean {
  if (lostAccess(access)) return false;
  if (
    decide({ systemRole: access.systemRole, studyRole: access.studyRole, blinding: access.blinding }, "data.read").allow
  )
    return true;
  return access.trial.status !== "completed" && access.trial.status !== "aborted";
}

/**
 * May the caller replay the trial's robot commands on the simulated robot?
 * Whoever may read its analysis (a replay shows its results), once it has ended.
 */
export function replayVerdict(access: TrialAccess): SocketVerdict {
  const lost = lostAccess(access);
  if (lost) return refuse(lost);
  const reading = decide(
    { systemRole: access.systemRole, studyRole: access.studyRole, blinding: access.blinding },
    "data.read",
  );
  if (!reading.allow) return refuse(reading.reason);
  if (access.trial.status !== "completed" && access.trial.status !== "aborted")
    return refuse("Only a finished trial can be replayed: this one has not ended yet.");
  return { allow: true, claim: false };
}

/**
 * May the caller watch the trial's robot camera? Whoever may follow its log
 * (the camera shows what the log describes). Stopping is never refused.
 */
export function cameraVerdict(access: TrialAccess, watch: boolean): SocketVerdict {
  const lost = lostAccess(access);
  if (lost) return refuse(lost);
  if (watch && !mayReadTrialLog(access)) return refuse("This trial has ended: its robot's camera ended with it.");
  return { allow: true, claim: false };
}

/**
 * May one connection pass a live video signal to another? Only within one
 * trial (the runtime looks the recipient up among that trial's connections),
 * and only between the video's source, someone who may run the trial, and a
 * watcher who may follow its log: observers never signal each other.
 */
export function signalVerdict(from: TrialAccess, to: TrialAccess): SocketVerdict {
  const lost = lostAccess(from);
  if (lost) return refuse(lost);
  if (lostAccess(to)) return refuse("That connection has left this trial.");
  if (from.trial.status === "completed" || from.trial.status === "aborted")
    return refuse("This trial has ended: its live video has ended with it.");
  const runs = (a: TrialAccess) => commandVerdict(a, "next").allow;
  const watcher = runs(from) ? to : runs(to) ? from : null;
  if (!watcher) return refuse("Live video goes between the trial's wizard and those watching: not between watchers.");
  if (!mayReadTrialLog(watcher)) return refuse("That person may not follow this trial.");
  return { allow: true, claim: false };
}

/** A change PostgreSQL announced on 'hri_access': the keys name what changed. */
export interface AccessChange {
  studyId?: string;
  userId?: string;
  trialId?: string;
}

/** Does the change concern this socket (its study, its user or its trial)? */
export function touches(change: AccessChange, socket: { userId: string; studyId: string; trialId: string }): boolean {
  if (change.trialId !== undefined) return change.trialId === socket.trialId;
  if (change.studyId !== undefined && change.studyId !== socket.studyId) return false;
  if (change.userId !== undefined && change.userId !== socket.userId) return false;
  return change.studyId !== undefined || change.userId !== undefined;
}
