// The rehearsal preview: the exact sequence a robot would perform for a chosen
// answer to each question, walked through the real engine without a trial.
// The designer shows it; tests use it to say what a path must be.
import { decide } from "./decide";
import { apply, initialState } from "./fold";
import { answerOptions, findStep, nextUnit } from "./protocol";
import type { Command, ProtocolAction, TrialProtocol, TrialState } from "./types";

export interface RehearsedStep {
  stepId: string;
  name: string;
  /** The step's number in the protocol (1-based), as the designer and the wizard's page show it, not the order of visits. */
  number: number;
  /** Actions in the order the engine requests them; those of one unit start together. */
  units: ProtocolAction[][];
  /** The answer recorded in this step, if it asks a question. */
  answer?: { actionId: string; optionId: string; label: string };
}

export interface Rehearsal {
  steps: RehearsedStep[];
  /** How it ended: at the protocol's end, or cut off after too many steps (a loop the answers never leave). */
  ending: "completed" | "looping";
}

/** More steps than any protocol would take: past it, the chosen answers keep the trial in a loop. */
const MAX_STEPS = 1000;

/** `answers` maps a question (record_answer action id) to an option id; unset questions take their first answer. */
export function rehearse(protocol: TrialProtocol, answers: Record<string, string> = {}): Rehearsal {
  let state = initialState(protocol);
  let seq = 0;
  const steps: RehearsedStep[] = [];
  const send = (command: Command) => {
    const decision = decide(protocol, state, command);
    if (!decision.ok) throw new Error(decision.reason);
    for (const event of decision.events) {
      state = apply(state, { ...event, seq: ++seq, relMs: seq });
      if (event.type === "step.entered") {
        const { step, index } = findStep(protocol, event.stepId)!;
        steps.push({ stepId: step.id, name: step.name, number: index + 1, units: [] });
      }
      if (event.type === "action.requested" && event.scripted) {
        const action = findStep(protocol, event.stepId)!.step.actions.find((a) => a.id === event.actionId)!;
        steps.at(-1)!.units.at(-1)!.push(action);
      }
      if (event.type === "answer.recorded")
        steps.at(-1)!.answer = { actionId: event.actionId, optionId: event.optionId, label: event.label };
    }
    return decision.events;
  };
  send({ kind: "start" });
  while (inProgress(state)) {
    if (steps.length > MAX_STEPS) return { steps, ending: "looping" };
    const unit = nextUnit(protocol, state);
    const question = unit[0]?.type === "record_answer" ? unit[0] : null;
    // A wait takes the wizard's way on in a preview: what the robot senses is not known before a trial.
    if (unit[0]?.type === "wait_for") {
      send({ kind: "go_on" });
      continue;
    }
    if (question) {
      const options = answerOptions(question);
      const chosen = options.find((o) => o.id === answers[question.id]) ?? options[0];
      if (!chosen) throw new Error(`The question "${question.name || question.id}" has no answers to choose from.`);
      send({ kind: "answer", actionId: question.id, optionId: chosen.id });
      continue;
    }
    if (unit.length > 0) steps.at(-1)!.units.push([]);
    const events = send({ kind: "next" });
    // The robot (and the clock, for pauses) finishes at once in a rehearsal.
    for (const event of events)
      if (event.type === "action.requested" && state.actions[event.actionId]?.status === "requested")
        send({ kind: "completed", actionId: event.actionId });
  }
  return { steps, ending: "completed" };
}

function inProgress(state: TrialState): boolean {
  return state.status === "in_progress";
}
