import { describe, expect, it } from "vitest";
import { type Command, simulate } from "@/core/trial";
import { fidelityReport } from "./fidelity";
import { studySummary } from "./study-summary";
import { reportFigures } from "./trial-figures";
import { done, perfect, protocol } from "./test-trial";

const report = (commands: Command[]) => fidelityReport(protocol, simulate(protocol, commands).log);
/** What a kept copy gives back: the figures written as JSON and read again. */
const keptAndRead = <T>(figures: T): T => JSON.parse(JSON.stringify(figures));

describe("the figures kept of a trial", () => {
  it.each<[string, Command[]]>([
    ["a perfect run", perfect],
    [
      "a run with a skip, an unscripted line and a jump by hand",
      [
        { kind: "start" },
        { kind: "unscripted", actionId: "x", actionType: "nod", parameters: {} },
        { kind: "skip", actionId: "wave" },
        { kind: "next" },
        ...done("hello"),
        { kind: "jump", stepId: "wrong" },
      ],
    ],
    ["a run that never started", []],
  ])("come back from JSON as they were, and give the study the tables its reports give: %s", (_, commands) => {
    const full = report(commands);
    const figures = keptAndRead(reportFigures(full));
    expect(figures).toEqual(reportFigures(full));
    expect(Object.keys(figures.deviations)).toEqual(Object.keys(full.deviations));
    const trial = { trialId: "t", participantCode: "P1", condition: null };
    expect(studySummary([{ ...trial, report: figures }])).toEqual(studySummary([{ ...trial, report: full }]));
  });
});
