import { describe as group, expect, it } from "vitest";
import type { RecordedAnswer } from "./answers";
import { byConditionCsv, resultsByCondition, type ConditionScore } from "./by-condition";
import type { FidelityReport, StepTiming } from "./fidelity";
import { describe } from "./study-summary";
import type { TrialFigures } from "./study-summary";

// A finished trial with just the figures these tables read: its fidelity, its deviations and its steps' times.
function trial(
  condition: string | null,
  executionFidelity: number,
  deviations: number,
  steps: Array<[string, number | null]>,
  answers: RecordedAnswer[] = [],
): TrialFigures {
  let at = 0;
  const timings: StepTiming[] = steps.map(([name, ms]) => {
    const enteredMs = ms === null ? null : at;
    if (ms !== null) at += ms;
    return {
      stepId: name,
      name,
      reached: ms !== null,
      entered: ms === null ? 0 : 1,
      enteredMs,
      leftMs: ms === null ? null : at,
      durationMs: ms,
    };
  });
  const report = {
    actions: [],
    steps: timings,
    unscripted: [],
    moves: { start: 0, next: 0, answer: 0, jump: 0, timer: 0, loop: 0, bound: 0, senses: 0, go_on: 0 },
    branches: { byLogic: 0, byHand: 0 },
    loops: [],
    answers,
    deviations: Object.fromEntries(deviations ? [["skipped", deviations]] : []),
    totals: {
      planned: 0,
      executed: 0,
      skipped: 0,
      failed: 0,
      notSent: 0,
      unknown: 0,
      timedOut: 0,
      notReached: 0,
      outOfOrder: 0,
      unscripted: 0,
    },
    executionFidelity,
    completed: true,
  } satisfies FidelityReport;
  return { trialId: `${condition}-${executionFidelity}`, participantCode: null, condition, report };
}

group("describing a measure", () => {
  it.each<[string, number[], ReturnType<typeof describe>]>([
    ["nothing", [], null],
    ["one value: no SD", [7], { n: 1, mean: 7, sd: null, median: 7, min: 7, max: 7 }],
    ["100, 80, 90", [100, 80, 90], { n: 3, mean: 90, sd: 10, median: 90, min: 80, max: 100 }],
    [
      "an even count: the median between the middle two",
      [1, 2, 3, 6],
      { n: 4, mean: 3, sd: Math.sqrt(14 / 3), median: 2.5, min: 1, max: 6 },
    ],
    ["all equal: SD 0", [5, 5], { n: 2, mean: 5, sd: 0, median: 5, min: 5, max: 5 }],
  ])("%s", (_, values, expected) => {
    expect(describe(values)).toEqual(expected);
  });
});

group("results by condition", () => {
  const trials = [
    trial("robot voice", 100, 0, [
      ["Greeting", 4000],
      ["Task", 60000],
    ]),
    trial("robot voice", 80, 2, [
      ["Greeting", 6000],
      ["Task", 50000],
    ]),
    trial("robot voice", 90, 1, [
      ["Greeting", 5000],
      ["Task", null],
    ]),
    trial("text on screen", 70, 3, [
      ["Greeting", 2000],
      ["Task", 30000],
    ]),
  ];
  const scores: ConditionScore[] = [
    { condition: "robot voice", questionnaire: "SUS", instrument: "sus", score: { ok: true, score: 60 } },
    { condition: "robot voice", questionnaire: "SUS", instrument: "sus", score: { ok: true, score: 80 } },
    { condition: "text on screen", questionnaire: "SUS", instrument: "sus", score: { ok: true, score: 75 } },
    {
      condition: "text on screen",
      questionnaire: "Godspeed",
      instrument: "godspeed",
      score: { ok: true, subscales: { likeability: 4.2 } },
    },
    // A questionnaire without a published score (free text, or not every item answered) adds nothing.
    { condition: "text on screen", questionnaire: "Notes", instrument: null, score: null },
  ];
  const results = resultsByCondition(trials, scores);
  const row = (measure: string) =>
    results.measures.find((m) => m.measure === measure)!.byCondition.map((c) => [c.condition, c.stats]);

  it("counts each condition's trials, conditions in alphabetical order", () => {
    expect(results.conditions).toEqual([
      { condition: "robot voice", trials: 3 },
      { condition: "text on screen", trials: 1 },
    ]);
  });

  it.each<[string, Array<[string, ReturnType<typeof describe>]>]>([
    [
      "Execution fidelity",
      [
        ["robot voice", { n: 3, mean: 90, sd: 10, median: 90, min: 80, max: 100 }],
        ["text on screen", { n: 1, mean: 70, sd: null, median: 70, min: 70, max: 70 }],
      ],
    ],
    [
      "Deviations per trial",
      [
        ["robot voice", { n: 3, mean: 1, sd: 1, median: 1, min: 0, max: 2 }],
        ["text on screen", { n: 1, mean: 3, sd: null, median: 3, min: 3, max: 3 }],
      ],
    ],
    [
      "Time in step: Greeting",
      [
        ["robot voice", { n: 3, mean: 5000, sd: 1000, median: 5000, min: 4000, max: 6000 }],
        ["text on screen", { n: 1, mean: 2000, sd: null, median: 2000, min: 2000, max: 2000 }],
      ],
    ],
    [
      // The third trial never reached the task: two values, not three.
      "Time in step: Task",
      [
        ["robot voice", { n: 2, mean: 55000, sd: Math.sqrt(50e6), median: 55000, min: 50000, max: 60000 }],
        ["text on screen", { n: 1, mean: 30000, sd: null, median: 30000, min: 30000, max: 30000 }],
      ],
    ],
    [
      // From the first step entered to the end of the last: 64 s, 56 s, and 5 s for the one that stopped early.
      "Trial duration",
      [
        ["robot voice", { n: 3, mean: 125000 / 3, sd: expect.any(Number), median: 56000, min: 5000, max: 64000 }],
        ["text on screen", { n: 1, mean: 32000, sd: null, median: 32000, min: 32000, max: 32000 }],
      ],
    ],
    [
      "Questionnaire score: SUS",
      [
        ["robot voice", { n: 2, mean: 70, sd: Math.sqrt(200), median: 70, min: 60, max: 80 }],
        ["text on screen", { n: 1, mean: 75, sd: null, median: 75, min: 75, max: 75 }],
      ],
    ],
    [
      "Questionnaire score: Godspeed (Likeability)",
      [
        ["robot voice", null],
        ["text on screen", { n: 1, mean: 4.2, sd: null, median: 4.2, min: 4.2, max: 4.2 }],
      ],
    ],
  ])("%s", (measure, expected) => {
    expect(row(measure)).toEqual(expected);
  });

  it("lists the measures: trial figures, then each step in protocol order, then the scores", () => {
    expect(results.measures.map((m) => m.measure)).toEqual([
      "Execution fidelity",
      "Deviations per trial",
      "Trial duration",
      "Time in step: Greeting",
      "Time in step: Task",
      "Questionnaire score: SUS",
      "Questionnaire score: Godspeed (Likeability)",
    ]);
  });

  it("puts participants without a condition last, and a condition with only answers has no trials", () => {
    const r = resultsByCondition(
      [trial(null, 50, 0, [])],
      [{ condition: "a", questionnaire: "SUS", instrument: "sus", score: { score: 10 } }],
    );
    expect(r.conditions).toEqual([
      { condition: "a", trials: 0 },
      { condition: null, trials: 1 },
    ]);
  });

  it("writes the tidy CSV: one row per condition and measure, units in the measure's name", () => {
    const csv = byConditionCsv(
      resultsByCondition([trial("=cmd", 100, 0, []), trial("=cmd", 80, 0, []), trial("b", 90, 0, [])], []),
    ).split("\r\n");
    expect(csv).toEqual([
      "condition,measure,n,mean,sd,median,min,max",
      // A condition named like a formula stays text in a spreadsheet.
      "'=cmd,Execution fidelity (%),2,90,14.142135623730951,90,80,100",
      "b,Execution fidelity (%),1,90,,90,90,90",
      "'=cmd,Deviations per trial,2,0,0,0,0,0",
      "b,Deviations per trial,1,0,,0,0,0",
      "'=cmd,Trial duration (ms),0,,,,,",
      "b,Trial duration (ms),0,,,,,",
      "",
    ]);
  });
});

group("answers by condition", () => {
  const PLANET = ["Mars", "Venus", "No answer"];
  const answer = (question: string, given: string, options = PLANET): RecordedAnswer => ({
    stepId: "s",
    actionId: question,
    question,
    answer: given,
    options,
    relMs: 0,
  });
  const answered = (condition: string | null, ...answers: RecordedAnswer[]) => trial(condition, 100, 0, [], answers);
  const counts = (trials: TrialFigures[]) =>
    resultsByCondition(trials, []).answers.map((q) => [
      q.question,
      q.answers.map((a) => [a.answer, ...a.byCondition.map((c) => c.count)]),
    ]);

  it.each<[string, TrialFigures[], unknown]>([
    ["no question asked: nothing to count", [answered("a"), answered("b")], []],
    [
      "every answer the question offered, the ones nobody gave at zero, per condition in order",
      [
        answered("praise", answer("Which planet?", "Mars")),
        answered("praise", answer("Which planet?", "Mars")),
        answered("neutral", answer("Which planet?", "Venus")),
        answered(null),
      ],
      [
        [
          "Which planet?",
          [
            ["Mars", 0, 2, 0],
            ["Venus", 1, 0, 0],
            ["No answer", 0, 0, 0],
          ],
        ],
      ],
    ],
    [
      "two questions apart, in the order first met; a question asked again counts each answer",
      [
        answered("a", answer("Ready?", "yes", ["yes", "no"]), answer("Ready?", "no", ["yes", "no"])),
        answered("a", answer("Which planet?", "Venus"), answer("Ready?", "yes", ["yes", "no"])),
      ],
      [
        [
          "Ready?",
          [
            ["yes", 2],
            ["no", 1],
          ],
        ],
        [
          "Which planet?",
          [
            ["Mars", 0],
            ["Venus", 1],
            ["No answer", 0],
          ],
        ],
      ],
    ],
    [
      // One experiment's version offered another answer than the other's: both are listed.
      "answers offered by either version of the question",
      [
        answered("a", answer("Which planet?", "Mars", ["Mars", "Venus"])),
        answered("b", answer("Which planet?", "Jupiter", ["Mars", "Jupiter"])),
      ],
      [
        [
          "Which planet?",
          [
            ["Mars", 1, 0],
            ["Venus", 0, 0],
            ["Jupiter", 0, 1],
          ],
        ],
      ],
    ],
  ])("%s", (_, trials, expected) => {
    expect(counts(trials)).toEqual(expected);
  });
});

group("answers by condition in the tidy CSV", () => {
  const asked = (condition: string | null, given: string): TrialFigures =>
    trial(
      condition,
      100,
      0,
      [],
      [{ stepId: "s", actionId: "q", question: "Which planet?", answer: given, options: ["Mars", "Venus"], relMs: 0 }],
    );
  it.each<[string, TrialFigures[], string[]]>([
    ["no question asked: no answer rows", [trial("a", 100, 0, [])], []],
    [
      "each answer's count per condition in n, the ones nobody gave at zero, as the Results tab counts them",
      [asked("praise", "Mars"), asked("praise", "Mars"), asked("neutral", "Venus"), asked(null, "Mars")],
      [
        "neutral,Answers to “Which planet?”: Mars,0,,,,,",
        "praise,Answers to “Which planet?”: Mars,2,,,,,",
        ",Answers to “Which planet?”: Mars,1,,,,,",
        "neutral,Answers to “Which planet?”: Venus,1,,,,,",
        "praise,Answers to “Which planet?”: Venus,0,,,,,",
        ",Answers to “Which planet?”: Venus,0,,,,,",
      ],
    ],
  ])("%s", (_, trials, rows) => {
    const lines = byConditionCsv(resultsByCondition(trials, [])).split("\r\n");
    expect(lines.filter((l) => l.includes("Answers to"))).toEqual(rows);
  });
});
