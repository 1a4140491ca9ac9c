// The protocol as a map: every way the trial can move from a step, for the
// designer's flow map. Read the way the engine walks (./decide.ts): a branch
// sends each answer to its step, "End trial" ends, and otherwise the step's
// "after" applies. A time limit (the step's, a question's) is an edge of its
// own, whatever else the step does; so is each event a "Wait for" waits for.
// A loop is two edges: back, with its bound, and on after its last time.
import type { After } from "../protocol/document";
import { awaitedEvents, exitBy, timeLimitsOf, timesWords, waysBy } from "../protocol/flow";
import { answerOptions, branchTarget } from "./protocol";
import type { TrialProtocol } from "./types";

export interface FlowEdge {
  from: number;
  /** A step's index, or the end of the trial. */
  to: number | "end";
  /**
   * "after": the step's own way on; "answer": a branch, labelled with its
   * answer; "timeout": a time limit, labelled with its seconds; "loop": a
   * step's way back, labelled with its bound (a time limit's way back is a
   * "timeout" with its bound in its label); "sensed": a wait's event,
   * labelled with the event.
   */
  kind: "after" | "answer" | "timeout" | "loop" | "sensed";
  label?: string;
}

export function flowEdges(protocol: TrialProtocol): FlowEdge[] {
  const indexOf = new Map(protocol.steps.map((s, i) => [s.id, i]));
  return protocol.steps.flatMap((_, from) => [
    ...routes(protocol, indexOf, from),
    ...timeouts(protocol, from),
    ...sensed(protocol, from),
  ]);
}

function sensed(protocol: TrialProtocol, from: number): FlowEdge[] {
  return protocol.steps[from]!.actions.flatMap((action) =>
    awaitedEvents(action).flatMap((e) => {
      const exit = exitBy(protocol.steps, from, e.after);
      if (exit.to === "missing") return [];
      return [{ from, to: exit.to === "end" ? "end" : exit.index, kind: "sensed" as const, label: e.event }];
    }),
  );
}

function timeouts(protocol: TrialProtocol, from: number): FlowEdge[] {
  return timeLimitsOf(protocol.steps[from]!).flatMap((limit) =>
    ways(protocol, from, limit.after).map((way) => ({
      ...way,
      kind: "timeout" as const,
      label: [`${limit.seconds} s`, way.label].filter(Boolean).join(", "),
    })),
  );
}

/** The edges `after` draws from the step `from`: one, or a loop's two; none to a step that is gone. */
function ways(protocol: TrialProtocol, from: number, after: After): FlowEdge[] {
  return waysBy(protocol.steps, from, after).flatMap(({ exit, loop }): FlowEdge[] => {
    if (exit.to === "missing") return [];
    const to = exit.to === "end" ? ("end" as const) : exit.index;
    if (loop) return [{ from, to, kind: "loop", label: `back, at most ${timesWords(loop.times)}` }];
    return [
      { from, to, kind: "after", ...(after.to === "again" ? { label: `after ${timesWords(after.times)}` } : {}) },
    ];
  });
}

function routes(protocol: TrialProtocol, indexOf: Map<string, number>, from: number): FlowEdge[] {
  const { steps } = protocol;
  const step = steps[from]!;
  const edges: FlowEdge[] = [];
  for (const [a, action] of step.actions.entries()) {
    if (action.type === "end_trial") return [...edges, { from, to: "end" as const, kind: "after" as const }];
    const question = step.actions[a - 1];
    if (action.type !== "branch" || question?.type !== "record_answer") continue;
    const options = answerOptions(question);
    for (const option of options) {
      const to = indexOf.get(branchTarget(action, option.id) ?? "");
      if (to !== undefined) edges.push({ from, to, kind: "answer", label: option.label });
    }
    // Every answer routed: the step's own way on is never taken.
    if (options.length && edges.filter((e) => e.kind === "answer").length === options.length) return edges;
  }
  return [...edges, ...ways(protocol, from, step.after ?? { to: "next" })];
}
