// Who took part in each condition, counted from the participants' and trials'
// rows as they stand: the methods text's "n per condition".
import type { TrialStatus } from "@/core/trial/types";

export interface EnrolledParticipant {
  id: string;
  consentStatus: "pending" | "given" | "declined" | "withdrawn";
  /** Between subjects: the one condition; within subjects: the conditions of their order. */
  conditionIds: string[];
}

export interface RunTrial {
  id: string;
  participantId: string;
  experimentId: string;
  status: TrialStatus;
}

export interface Enrolment {
  enrolled: number;
  completed: number;
  withdrawn: number;
  excluded: Array<{ reason: string; n: number }>;
}

/** The condition a trial ran in: the participant's condition whose experiment it ran (null when none). */
export function conditionOfTrial(
  trial: Pick<RunTrial, "participantId" | "experimentId">,
  participants: Map<string, EnrolledParticipant>,
  experimentOf: Map<string, string>,
): string | null {
  const assigned = participants.get(trial.participantId)?.conditionIds ?? [];
  return assigned.find((c) => experimentOf.get(c) === trial.experimentId) ?? null;
}

export function enrolment(
  conditionId: string,
  participants: EnrolledParticipant[],
  trials: RunTrial[],
  experimentOf: Map<string, string>,
): Enrolment {
  const byId = new Map(participants.map((p) => [p.id, p]));
  const inIt = participants.filter((p) => p.conditionIds.includes(conditionId));
  const ran = (p: EnrolledParticipant, status: RunTrial["status"]) =>
    trials.some(
      (t) => t.participantId === p.id && t.status === status && conditionOfTrial(t, byId, experimentOf) === conditionId,
    );
  const staying = inIt.filter((p) => p.consentStatus !== "withdrawn");
  return {
    enrolled: inIt.length,
    completed: staying.filter((p) => ran(p, "completed")).length,
    withdrawn: inIt.length - staying.length,
    excluded: [
      { reason: "declined consent", n: staying.filter((p) => p.consentStatus === "declined").length },
      {
        reason: "whose trial was stopped before its end",
        n: staying.filter((p) => p.consentStatus !== "declined" && ran(p, "aborted") && !ran(p, "completed")).length,
      },
    ],
  };
}
