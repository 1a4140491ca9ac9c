import { describe, expect, it } from "vitest";
import { simulate, type Command } from "@/core/trial";
import { fidelityReport } from "./fidelity";
import { spread, studySummary } from "./study-summary";
import { done, perfect, protocol } from "./test-trial";

const trial = (trialId: string, commands: Command[], msPerEvent = 10) => ({
  trialId,
  participantCode: trialId.toUpperCase(),
  condition: trialId === "p3" ? "voice" : "gestures",
  report: fidelityReport(protocol, simulate(protocol, commands, (i) => i * msPerEvent).log),
});

describe("the study-level summary", () => {
  const summary = studySummary([
    trial("p1", perfect),
    trial("p2", perfect, 20),
    trial("p3", [{ kind: "start" }, { kind: "skip", actionId: "wave" }, { kind: "next" }, ...done("hello")]),
  ]);

  it("lists each trial's figures", () => {
    expect(
      summary.trials.map((t) => [t.participantCode, t.condition, t.completed, t.executionFidelity, t.deviations]),
    ).toEqual([
      ["P1", "gestures", true, 100, 0],
      ["P2", "gestures", true, 100, 0],
      ["P3", "voice", false, 50, 1],
    ]);
    expect(summary.trials[1]!.durationMs).toBe(2 * summary.trials[0]!.durationMs!);
  });

  it("times each step across participants, in protocol order, counting who reached it", () => {
    expect(summary.steps.map((s) => [s.name, s.reachedBy])).toEqual([
      ["Introduction", 3],
      ["Question", 2],
      ["Right", 2],
      ["Wrong", 0],
    ]);
    // p3 is still in the introduction when its log ends: timed up to its last event.
    const intro = summary.steps[0]!.durationMs!;
    expect(intro.n).toBe(3);
    expect(summary.steps[1]!.durationMs).toMatchObject({ n: 2 });
    expect(summary.steps[1]!.durationMs!.max).toBe(2 * summary.steps[1]!.durationMs!.min);
    expect(summary.steps[3]!.durationMs).toBeNull();
  });

  it("sums up how consistently the protocol was run", () => {
    expect(summary.consistency).toMatchObject({
      trials: 3,
      completed: 2,
      withoutDeviation: 2,
      deviationsByKind: { skipped: 1 },
    });
    expect(summary.consistency.meanFidelity).toBeCloseTo(83.33, 2);
    expect(summary.consistency.sdFidelity).toBeCloseTo(28.87, 2);
    expect(studySummary([]).consistency).toEqual({
      trials: 0,
      completed: 0,
      meanFidelity: null,
      sdFidelity: null,
      withoutDeviation: 0,
      deviationsByKind: {},
    });
  });

  it.each<[number[], ReturnType<typeof spread>]>([
    [[], null],
    [[5], { n: 1, median: 5, min: 5, max: 5 }],
    [[9, 1, 4, 6], { n: 4, median: 5, min: 1, max: 9 }],
  ])("spreads %j", (values, expected) => {
    expect(spread(values)).toEqual(expected);
  });
});
