// The rehearsal preview: the exact sequence a robot would perform for a chosen
// answer to each question and a chosen happening at each wait (an awaited
// event, the wizard's go on, or its time running out), walked through the
// real engine without a trial.
// The designer shows it; tests use it to say what a path must be.
import { decide } from "./decide";
import { apply, initialState } from "./fold";
import { answerOptions, findStep, nextUnit } from "./protocol";
import { awaitedEvents } from "../protocol/flow";
import type { Command, ProtocolAction, RunningTimer, TrialProtocol, TrialState } from "./types";

export interface RehearsedStep {
  stepId: string;
  name: string;
  /** The step's number in the protocol (1-based), as the designer and the wizard's page show it, not the order of visits. */
  number: number;
  /** Actions in the order the engine requests them; those of one unit start together. */
  units: ProtocolAction[][];
  /** Entered back round a loop: how many times that loop has now gone back. */
  again?: number;
  /** The answer recorded in this step, if it asks a question. */
  answer?: { actionId: string; optionId: string; label: string };
  /** The awaited event that happened here, if a wait took one's edge: the robot's plugin's event id. */
  sensed?: { actionId: string; event: string };
  /** The time limit that ran out here, if one did: a question's ("no answer in …") or the step's. */
  timeout?: { seconds: number; question: boolean };
}

export interface Rehearsal {
  steps: RehearsedStep[];
  /** How it ended: at the protocol's end, or cut off after too many steps (a loop the answers never leave). */
  ending: "completed" | "looping";
}

/** More steps than any protocol would take: past it, the chosen answers keep the trial in a loop. */
const MAX_STEPS = 1000;

/**
 * `choices` says what happens at each point of choice, by its action id: a question's answer (an option id;
 * unset, its first answer), a wait's awaited event (the event's option id, the edge's; unset, the wizard's
 * go on).
 * `runOut` holds the steps and questions whose time limit the rehearsal lets run out: a question's at the
 * question, unanswered; a step's once its actions are done, the wizard never moving on.
 */
export function rehearse(
  protocol: TrialProtocol,
  choices: Record<string, string> = {},
  runOut: ReadonlySet<string> = new Set(),
): Rehearsal {
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
        const again = event.via === "loop" && event.loop ? { again: state.loops[event.loop] } : {};
        steps.push({ stepId: step.id, name: step.name, number: index + 1, units: [], ...again });
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
  /** Lets the running timer `matches` picks run out, if there is one: the trial takes its limit's edge. */
  const timeRunsOut = (matches: (timer: RunningTimer) => boolean) => {
    const running = Object.entries(state.timers).find(([, timer]) => matches(timer));
    if (!running) return false;
    const [timerId, timer] = running;
    steps.at(-1)!.timeout = { seconds: timer.seconds, question: timer.actionId !== undefined };
    send({ kind: "timer_fired", timerId });
    return true;
  };
  send({ kind: "start" });
  while (inProgress(state)) {
    if (steps.length > MAX_STEPS) return { steps, ending: "looping" };
    const unit = nextUnit(protocol, state);
    const question = unit[0]?.type === "record_answer" ? unit[0] : null;
    if (question && runOut.has(question.id) && timeRunsOut((t) => t.actionId === question.id)) continue;
    const stepId = state.currentStepId;
    if (!unit.length && stepId && runOut.has(stepId) && timeRunsOut((t) => t.stepId === stepId && !t.actionId))
      continue;
    // A wait: the event chosen to happen (the robot's own time and message play no part in a preview), its
    // time let run out, or else the wizard's go on.
    if (unit[0]?.type === "wait_for") {
      const wait = unit[0];
      const happens = awaitedEvents(wait).find((e) => e.id === choices[wait.id]);
      if (happens) {
        steps.at(-1)!.sensed = { actionId: wait.id, event: happens.event };
        send({ kind: "sensed", event: happens.event, at: seq, message: null });
      } else if (!(runOut.has(wait.id) && timeRunsOut((t) => t.actionId === wait.id))) send({ kind: "go_on" });
      continue;
    }
    if (question) {
      const options = answerOptions(question);
      const chosen = options.find((o) => o.id === choices[question.id]) ?? options[0];
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
