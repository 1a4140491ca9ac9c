// A loop must go back, and must come out. "Go back to <step>, at most K
// times, then …" is refused when its step is further on (that is a "go to"),
// or when what comes after its last time is inside the loop again, so the
// trial could only go round.
import { exitBy, timeLimitsOf, timesWords } from "../protocol/flow";
import { stepLabel, upper } from "./step-label";
import type { DesignStep } from "./types";
import type { DesignIssue } from "./validate";

/** `exits`: the steps each step may lead to, as the flow checks read them (loops both ways). */
export function loopIssues(steps: DesignStep[], exits: number[][]): Array<{ step: number; issue: DesignIssue }> {
  const issues: Array<{ step: number; issue: DesignIssue }> = [];
  steps.forEach((step, s) => {
    const add = (code: string, message: string) =>
      issues.push({ step: s, issue: { severity: "error", code, message, stepId: step.id } });
    for (const after of [step.after, ...timeLimitsOf(step).map((limit) => limit.after)]) {
      if (after?.to !== "again") continue;
      const back = steps.findIndex((other) => other.id === after.stepId);
      // A step that is gone is told as such by the flow checks.
      if (back < 0) continue;
      const [from, to] = [stepLabel(step, s), stepLabel(steps[back]!, back)];
      if (back > s) {
        add(
          "loop_forward",
          `${upper(from)} goes back to ${to}, which comes after it. A loop can only go back to this step or an earlier one; to go further on, choose "Go to" that step.`,
        );
        continue;
      }
      const onward = exitBy(steps, s, after.onward);
      if (onward.to !== "step" || !inside(exits, back, s).has(onward.index)) continue;
      add(
        "loop_no_way_out",
        `The loop from ${from} back to ${to} has no way out: after going back ${timesWords(after.times)} it goes on to ${stepLabel(steps[onward.index]!, onward.index)}, which is inside the loop. Choose where it goes after its last time: a step outside the loop, or the end of the trial.`,
      );
    }
  });
  return issues;
}

/** The steps of the loop from `last` back to `first`: those reached from `first` that lead on to `last`. */
function inside(exits: number[][], first: number, last: number): Set<number> {
  const into: number[][] = exits.map(() => []);
  exits.forEach((to, from) => to.forEach((t) => into[t]!.push(from)));
  const leading = closure(last, into);
  return new Set([...closure(first, exits)].filter((s) => leading.has(s)));
}

function closure(start: number, edges: number[][]): Set<number> {
  const seen = new Set([start]);
  for (const s of seen) for (const next of edges[s]!) seen.add(next);
  return seen;
}
