// The protocol as a map: every way the trial can move from a step, for the
// designer's flow map. Read the way the engine walks (./decide.ts): a branch
// sends each answer to its step, "End trial" ends, and otherwise the step's
// "after" applies.
import { exitOf } from "../protocol/flow";
import { answerOptions, branchTarget } from "./protocol";
import type { TrialProtocol } from "./types";

export interface FlowEdge {
  from: number;
  /** A step's index, or the end of the trial. */
  to: number | "end";
  /** "after": the step's own way on; "answer": a branch, labelled with its answer. */
  kind: "after" | "answer";
  label?: string;
}

export function flowEdges(protocol: TrialProtocol): FlowEdge[] {
  const { steps } = protocol;
  const indexOf = new Map(steps.map((s, i) => [s.id, i]));
  return steps.flatMap((step, from) => {
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
    const exit = exitOf(steps, from);
    if (exit.to === "step") edges.push({ from, to: exit.index, kind: "after" });
    if (exit.to === "end") edges.push({ from, to: "end", kind: "after" });
    return edges;
  });
}
