// The participant's answers as data: each answer the wizard recorded, with
// the question it answers and the answers that question offered, so the
// analysis page, the exports, ELAN and the Results tab read the same values.
import { actionName, type ActionNames } from "@/core/designer/action-name";
import { answerOptions, type TrialEvent, type TrialProtocol } from "@/core/trial";
import type { ProtocolAction } from "@/core/trial/types";

export interface RecordedAnswer {
  stepId: string;
  actionId: string;
  /** The question as the researcher wrote it for the wizard (or the action's name, when it has no text). */
  question: string;
  /** The answer recorded, by its label. */
  answer: string;
  /** Every answer the question offered, in the designer's order: the ones nobody gave count too. */
  options: string[];
  relMs: number | null;
}

/** The answer an event records, by its label; undefined for any other event. */
export function answerOf(event: object): string | undefined {
  const e = event as { type?: string; label?: unknown };
  return e.type === "answer.recorded" && typeof e.label === "string" ? e.label : undefined;
}

/** A question by its label, else its full text for the wizard, else its block's name. */
export function questionOf(action: ProtocolAction, names?: ActionNames): string {
  const prompt = action.parameters.prompt;
  const text = typeof prompt === "string" ? prompt.trim() : "";
  return action.name?.trim() || text || actionName(action, names);
}

/** Every answer recorded in the trial, in log order: a question asked again counts each time it was answered. */
export function recordedAnswers(
  protocol: TrialProtocol,
  events: readonly TrialEvent[],
  names?: ActionNames,
): RecordedAnswer[] {
  const questions = new Map(protocol.steps.flatMap((s) => s.actions.map((a) => [a.id, a])));
  return events.flatMap((e) => {
    if (e.type !== "answer.recorded") return [];
    const action = questions.get(e.actionId);
    return [
      {
        stepId: e.stepId,
        actionId: e.actionId,
        question: action ? questionOf(action, names) : e.actionId,
        answer: e.label,
        options: action ? answerOptions(action).map((o) => o.label) : [e.label],
        relMs: e.relMs,
      },
    ];
  });
}
