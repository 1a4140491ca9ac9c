import { describe, expect, it } from "vitest";
import { type Command, simulate, type TrialProtocol } from "@/core/trial";
import { fidelityReport } from "./fidelity";
import { moveWords, stepVisits } from "./moves";

// "Ask again, at most twice, then goodbye".
const protocol: TrialProtocol = {
  steps: [
    {
      id: "ask",
      name: "Question",
      after: { to: "again", stepId: "ask", times: 2, onward: { to: "next" } },
      actions: [{ id: "q", type: "say", parameters: { text: "What color?" } }],
    },
    { id: "bye", name: "Goodbye", actions: [{ id: "bye-say", type: "say", parameters: { text: "Bye" } }] },
  ],
};
const round: Command[] = [{ kind: "next" }, { kind: "completed", actionId: "q" }, { kind: "next" }];
const run = (rounds: number): Command[] => [{ kind: "start" }, ...Array.from({ length: rounds }, () => round).flat()];
const report = (rounds: number) => fidelityReport(protocol, simulate(protocol, run(rounds)).log);

describe("a loop's iterations in the fidelity report", () => {
  it.each<[string, number, { taken: number; boundReached: boolean }, [number, number]]>([
    ["asked once, not yet round", 0, { taken: 0, boundReached: false }, [1, 0]],
    ["back once: under its bound", 1, { taken: 1, boundReached: false }, [2, 0]],
    ["back twice: at its bound, still in the step", 2, { taken: 2, boundReached: false }, [3, 0]],
    ["its bound reached: on to the next step", 3, { taken: 2, boundReached: true }, [3, 1]],
  ])("%s", (_, rounds, loop, entered) => {
    const r = report(rounds);
    expect(r.loops).toEqual([{ loop: "after:ask", stepId: "ask", backToStepId: "ask", times: 2, ...loop }]);
    expect(r.steps.map((s) => s.entered)).toEqual(entered);
  });

  it("and the analysis names what moved the trial: the loop each time round, then its bound", () => {
    const visits = stepVisits(simulate(protocol, run(3)).log);
    expect(visits.map((v) => [v.stepId, moveWords(v.move)])).toEqual([
      ["ask", "the start"],
      ["ask", "the loop going back (time 1)"],
      ["ask", "the loop going back (time 2)"],
      ["bye", "a loop's bound (2 times) reached"],
    ]);
  });
});
