// What moved the trial at each step: the path it took, each step it entered
// with what took it there (the start, the wizard's next, the participant's
// answer through a branch, a time limit running out, a loop going back or its
// bound reached, the robot's senses or the wizard's go on ending a wait, or a
// jump, which is a deviation) and how many of
// the step's actions the wizard skipped while in it. Read from the log only,
// so a step entered twice is two visits.
import type { TrialEvent } from "@/core/trial";
import { timesWords } from "@/core/protocol/flow";
import type { EventBody } from "@/core/trial/types";

type Via = Extract<EventBody, { type: "step.entered" }>["via"];

export type Move =
  | { by: "start" }
  | { by: "next" }
  | { by: "answer"; answer: string }
  | { by: "jump" }
  | { by: "timer" }
  /** Back round a loop: `round` is how many times this loop has now gone back. */
  | { by: "loop"; round: number }
  /** A loop went back its `times`, so the trial took its way on ("onward"). */
  | { by: "bound"; times: number }
  | { by: "senses"; event: string }
  | { by: "go_on" };

/**
 * Each way the engine enters a step, as the move a reader is told. A new way
 * (a timer that fires, a loop's bound reached) is a new `via` of step.entered:
 * it must be given its move here, and its words in MOVE_WORDS.
 */
const MOVED_BY: Record<Via, Move["by"]> = {
  start: "start",
  next: "next",
  branch: "answer",
  manual_jump: "jump",
  timeout: "timer",
  loop: "loop",
  loop_bound: "bound",
  sensed: "senses",
  go_on: "go_on",
};

export interface StepVisit {
  /** The step.entered event's seq. */
  seq: number;
  stepId: string;
  enteredMs: number | null;
  move: Move;
  /** Actions of this step the wizard skipped during this visit. */
  skipped: number;
}

export function stepVisits(events: readonly TrialEvent[]): StepVisit[] {
  const visits: StepVisit[] = [];
  let lastAnswer: string | undefined;
  let lastBound = 0;
  let lastSensed: string | undefined;
  const rounds = new Map<string, number>();
  for (const e of events) {
    if (e.type === "answer.recorded") lastAnswer = e.label;
    if (e.type === "loop.bound_reached") lastBound = e.times;
    if (e.type === "robot.sensed") lastSensed = e.event;
    if (e.type === "action.skipped" && visits.length) visits.at(-1)!.skipped++;
    if (e.type !== "step.entered") continue;
    const by = MOVED_BY[e.via];
    const round = (rounds.get(e.loop ?? "") ?? 0) + 1;
    if (by === "loop") rounds.set(e.loop ?? "", round);
    // A branch enters its step right after the answer it follows, a loop's way on right after its
    // bound (loops.ts writes them together), a wait's edge right after the robot's event (waits.ts).
    const move: Move =
      by === "answer"
        ? { by, answer: lastAnswer ?? "" }
        : by === "loop"
          ? { by, round }
          : by === "bound"
            ? { by, times: lastBound }
            : by === "senses"
              ? { by, event: lastSensed ?? "" }
              : { by };
    visits.push({ seq: e.seq, stepId: e.stepId, enteredMs: e.relMs, move, skipped: 0 });
  }
  return visits;
}

const MOVE_WORDS: Record<Move["by"], (move: Move) => string> = {
  start: () => "the start",
  next: () => "the wizard's next",
  answer: (move) => `the answer “${(move as Extract<Move, { by: "answer" }>).answer}”`,
  jump: () => "the wizard's jump (a deviation)",
  timer: () => "the time limit running out",
  loop: (move) => `the loop going back (time ${(move as Extract<Move, { by: "loop" }>).round})`,
  bound: (move) => `a loop's bound (${timesWords((move as Extract<Move, { by: "bound" }>).times)}) reached`,
  senses: (move) => `the robot's senses (“${(move as Extract<Move, { by: "senses" }>).event}”)`,
  go_on: () => "the wizard's go on",
};

/** What moved the trial into a step, in words: "the answer “Mars”". */
export function moveWords(move: Move): string {
  return MOVE_WORDS[move.by](move);
}
