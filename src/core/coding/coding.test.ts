import { describe, expect, it } from "vitest";
import { tableCsv } from "@/core/analysis/table";
import { type AgreementWindow, type Counted, countedWords, sameCount } from "./counted";
import { agreement, type CodeMark, cohenKappa, confusion, NONE, sliceCodes, strength, windowSpans } from "./agreement";
import { codesTable } from "./export";
import { checkScheme, codeForKey } from "./scheme";
import { blankScheme, newCode, SCHEME_TEMPLATES, schemeTemplate } from "./templates";

const code = (id: string, key: string, kind: "point" | "state" = "point") => ({
  id,
  name: id,
  key,
  colour: "#2563eb",
  kind,
  modifiers: [],
});
const scheme = (sets: Array<{ id: string; codes: unknown[] }>) => ({
  name: "S",
  sets: sets.map((s) => ({ name: s.id, ...s })),
});

describe("a coding scheme", () => {
  it.each<[string, unknown, string[]]>([
    ["a valid scheme", scheme([{ id: "gaze", codes: [code("robot", "r", "state"), code("away", "a", "state")] }]), []],
    ["no sets", { name: "S", sets: [] }, ["sets: needs at least one set of codes"]],
    ["an empty set", scheme([{ id: "gaze", codes: [] }]), ["sets.0.codes: needs at least one code"]],
    [
      "one key for two codes, in two sets",
      scheme([
        { id: "a", codes: [code("x", "x")] },
        { id: "b", codes: [code("y", "X")] },
      ]),
      ['sets.1.codes.0.key: "x" is already the key of x'],
    ],
    [
      "a code id twice in a set",
      scheme([{ id: "a", codes: [code("x", "1"), code("x", "2")] }]),
      ['sets.0.codes.1.id: "x" is used twice in this set'],
    ],
    [
      "a set id twice",
      scheme([
        { id: "a", codes: [code("x", "1")] },
        { id: "a", codes: [code("y", "2")] },
      ]),
      ['sets.1.id: "a" is used twice'],
    ],
    [
      "a key of two letters",
      scheme([{ id: "a", codes: [code("x", "ab")] }]),
      ["sets.0.codes.0.key: must be one key: a letter, a digit or a punctuation mark"],
    ],
    [
      "Space as a key",
      scheme([{ id: "a", codes: [code("x", " ")] }]),
      ["sets.0.codes.0.key: must be one key: a letter, a digit or a punctuation mark"],
    ],
    [
      "a colour by name",
      scheme([{ id: "a", codes: [{ ...code("x", "1"), colour: "red" }] }]),
      ["sets.0.codes.0.colour: must be a colour like #3b82f6"],
    ],
    [
      "a kind that is neither",
      scheme([{ id: "a", codes: [{ ...code("x", "1"), kind: "span" }] }]),
      ['sets.0.codes.0.kind: Invalid option: expected one of "point"|"state"'],
    ],
    [
      "a modifier twice",
      scheme([{ id: "a", codes: [{ ...code("x", "1"), modifiers: ["verbal", "verbal"] }] }]),
      ["sets.0.codes.0.modifiers: a modifier is listed twice"],
    ],
    [
      "an id with spaces",
      scheme([{ id: "my set", codes: [code("x", "1")] }]),
      ["sets.0.id: may hold only lower-case letters, digits, - and _"],
    ],
  ])("%s", (_name, input, problems) => {
    const checked = checkScheme(input);
    expect(checked.ok ? [] : checked.problems).toEqual(problems);
  });

  it.each(SCHEME_TEMPLATES)("the template %s is a valid scheme", (t) => {
    expect(checkScheme(schemeTemplate(t))).toEqual({ ok: true, scheme: schemeTemplate(t) });
  });

  it("the wizard-intervention template holds the four types, mutually exclusive, one key each", () => {
    const s = schemeTemplate("wizard-interventions");
    expect(s.sets.map((set) => set.codes.map((c) => `${c.name}:${c.key}`))).toEqual([
      ["Technical:t", "Clarification:c", "Hint:h", "Guidance:g"],
    ]);
  });

  it("a blank scheme is valid, and a key finds its code whatever its case", () => {
    expect(checkScheme(blankScheme("Mine")).ok).toBe(true);
    const s = checkScheme(schemeTemplate("participant-engagement"));
    expect(s.ok && codeForKey(s.scheme, "R")?.code.id).toBe("robot");
    expect(s.ok && codeForKey(s.scheme, "z")).toBeUndefined();
  });
});

describe("Cohen's kappa", () => {
  // Worked examples of Wikipedia's "Cohen's kappa" article (sections "Simple
  // example" and "Same percentages but different numbers"), which follow
  // Cohen (1960): rows are rater A (Yes, No), columns rater B (Yes, No).
  // https://en.wikipedia.org/wiki/Cohen%27s_kappa
  it.each<[string, number[][], number, number, number]>([
    [
      "the simple example (50 grant proposals)",
      [
        [20, 5],
        [10, 15],
      ],
      0.7,
      0.5,
      0.4,
    ],
    [
      "the first table of the same-percentage pair",
      [
        [45, 15],
        [25, 15],
      ],
      0.6,
      0.54,
      0.1304,
    ],
    [
      "the second table of the same-percentage pair",
      [
        [25, 35],
        [5, 35],
      ],
      0.6,
      0.46,
      0.2593,
    ],
  ])("%s", (_name, counts, observed, expected, kappa) => {
    const k = cohenKappa(counts);
    expect(k.observed).toBeCloseTo(observed, 4);
    expect(k.expected).toBeCloseTo(expected, 4);
    expect(k.kappa).toBeCloseTo(kappa, 4);
  });

  it.each<[string, number[][], number | null]>([
    [
      "perfect agreement",
      [
        [3, 0],
        [0, 7],
      ],
      1,
    ],
    [
      "no slices at all",
      [
        [0, 0],
        [0, 0],
      ],
      null,
    ],
    [
      "both always said the same one code: chance agreement is certain",
      [
        [9, 0],
        [0, 0],
      ],
      null,
    ],
    [
      "systematic disagreement",
      [
        [0, 5],
        [5, 0],
      ],
      -1,
    ],
  ])("%s", (_name, counts, kappa) => {
    expect(cohenKappa(counts).kappa).toBe(kappa);
  });

  // Landis, J. R. & Koch, G. G. (1977). The measurement of observer agreement
  // for categorical data. Biometrics 33(1), 159–174: their bands.
  it.each<[number, string]>([
    [-0.1, "poor"],
    [0.2, "slight"],
    [0.4, "fair"],
    [0.5, "moderate"],
    [0.7, "substantial"],
    [0.81, "almost perfect"],
  ])("κ = %s is %s", (kappa, words) => expect(strength(kappa)).toBe(words));
});

describe("slicing two observers' codes", () => {
  const state = (codeId: string, startMs: number, endMs: number | null): CodeMark => ({
    setId: "gaze",
    codeId,
    kind: "state",
    startMs,
    endMs,
  });
  const point = (codeId: string, startMs: number): CodeMark => ({
    setId: "gaze",
    codeId,
    kind: "point",
    startMs,
    endMs: null,
  });

  it.each<[string, CodeMark[], string[]]>([
    ["nothing coded", [], [NONE, NONE, NONE, NONE]],
    ["a state over the middle two slices", [state("robot", 1000, 3000)], [NONE, "robot", "robot", NONE]],
    ["a state not yet ended holds to the end", [state("away", 2000, null)], [NONE, NONE, "away", "away"]],
    ["a state that misses a slice's middle does not mark it", [state("robot", 600, 1400)], [NONE, NONE, NONE, NONE]],
    [
      "a point event marks its slice, over a state",
      [state("robot", 0, 4000), point("smile", 2100)],
      ["robot", "robot", "smile", "robot"],
    ],
    [
      "another set's codes are not this set's",
      [{ ...state("robot", 0, 4000), setId: "other" }],
      [NONE, NONE, NONE, NONE],
    ],
  ])("%s", (_name, marks, slices) => {
    expect(sliceCodes(marks, "gaze", 4000, 1000)).toEqual(slices);
  });

  it("two observers' slices make the confusion table and the kappa, pooled over trials", () => {
    const sets = [{ id: "gaze", codes: [{ id: "robot" }, { id: "away" }] }];
    const one = {
      durationMs: 4000,
      a: [state("robot", 0, 2000), state("away", 2000, 4000)],
      b: [state("robot", 0, 3000), state("away", 3000, 4000)],
    };
    const [single] = agreement(sets, [one], 1000);
    expect(single!.table).toEqual({
      categories: ["robot", "away", NONE],
      counts: [
        [2, 0, 0],
        [1, 1, 0],
        [0, 0, 0],
      ],
    });
    expect(single!.kappa).toBeCloseTo(0.5, 6);
    const [pooled] = agreement(sets, [one, one], 1000);
    expect(pooled!.table.counts[0]).toEqual([4, 0, 0]);
    expect(pooled!.n).toBe(8);
    expect(pooled!.kappa).toBeCloseTo(0.5, 6);
  });

  // Observer A codes from 0 s, B only from 2 s; the trial ends at 4.3 s, so a 1 s slicing has a fifth slice past the end.
  const windowed = {
    durationMs: 4300,
    a: [state("robot", 0, 1000), state("away", 1000, 4300)],
    b: [state("away", 2000, 4300)],
    steps: [
      { stepId: "greet", fromMs: 0, toMs: 3000 },
      { stepId: "ask", fromMs: 3000, toMs: 4300 },
    ],
  };
  it.each<[AgreementWindow, string[], Array<[number, number]>, number[][]]>([
    // Slices 0 and 1 (robot/away vs none) disagree; 2 and 3 agree; the fifth, past the end, no longer counts.
    [
      "trial",
      [],
      [[0, 4300]],
      [
        [0, 0, 1],
        [0, 2, 1],
        [0, 0, 0],
      ],
    ],
    [
      "bothCoding",
      [],
      [[2000, 4300]],
      [
        [0, 0, 0],
        [0, 2, 0],
        [0, 0, 0],
      ],
    ],
    [
      "steps",
      ["ask"],
      [[3000, 4300]],
      [
        [0, 0, 0],
        [0, 1, 0],
        [0, 0, 0],
      ],
    ],
    [
      "steps",
      [],
      [],
      [
        [0, 0, 0],
        [0, 0, 0],
        [0, 0, 0],
      ],
    ],
  ])("the %s window (steps %j) counts %j", (window, stepIds, spans, counts) => {
    expect(windowSpans(windowed, "gaze", window, stepIds)).toEqual(spans);
    const [set] = agreement(
      [{ id: "gaze", codes: [{ id: "robot" }, { id: "away" }] }],
      [windowed],
      1000,
      window,
      stepIds,
    );
    expect(set!.table.counts).toEqual(counts);
  });

  it("is reproduced from the codes CSV with the window the report names", () => {
    const scheme = {
      ...blankScheme("Gaze"),
      sets: [{ id: "gaze", name: "Gaze", codes: [code("robot", "1", "state"), code("away", "2", "state")] }],
    };
    const rows = (["a", "b"] as const).flatMap((observer) =>
      windowed[observer].map((m) => ({
        trialId: "t1",
        observer,
        scheme,
        schemeVersion: 1,
        setId: m.setId,
        codeId: m.codeId,
        kind: m.kind,
        startMs: m.startMs,
        endMs: m.endMs,
        modifiers: [],
      })),
    );
    // Read back as a researcher would: slice each observer's states from the CSV, from when both had coded.
    const [header, ...lines] = tableCsv(codesTable(rows)).trim().split(/\r?\n/);
    const col = (name: string) => header!.split(",").indexOf(name);
    const read = lines.map((l) => l.split(","));
    const of = (observer: string) => read.filter((r) => r[col("observer")] === observer);
    const start = Math.max(...["a", "b"].map((o) => Math.min(...of(o).map((r) => Number(r[col("start_ms")])))));
    const at = (observer: string, ms: number) =>
      of(observer).find((r) => Number(r[col("start_ms")]) <= ms && ms < Number(r[col("end_ms")]))?.[col("code")] ??
      NONE;
    const middles = [0, 1, 2, 3].map((i) => (i + 0.5) * 1000).filter((ms) => ms >= start && ms < 4300);
    const agreed = middles.filter((ms) => at("a", ms) === at("b", ms)).length;
    const [set] = agreement(scheme.sets, [windowed], 1000, "bothCoding");
    expect(set!.n).toBe(middles.length);
    expect(set!.observed).toBe(agreed / middles.length);
  });

  it("refuses slices of different lengths, and a code the set does not have", () => {
    expect(() => confusion(["a"], [], ["a"])).toThrow("1 and 0 slices");
    expect(() => confusion(["a"], ["b"], ["a"])).toThrow('"b" is not a category');
  });
});

describe("a new code", () => {
  it("takes the first key no code has, and stays valid when added", () => {
    const s = blankScheme("Mine");
    const added = newCode(s);
    expect(added.key).toBe("2");
    expect(added.id).toBe("code-2");
    s.sets[0]!.codes.push(added);
    expect(checkScheme(s).ok).toBe(true);
  });
});

describe("what a kappa counted, said beside it", () => {
  const steps = [
    { id: "s1", name: "Story" },
    { id: "s2", name: "Recall" },
  ];
  it.each<[Counted, string]>([
    [{ sliceMs: 1000, window: "trial", stepIds: [] }, "1 s slices, the whole trial"],
    [{ sliceMs: 500, window: "bothCoding", stepIds: [] }, "0.5 s slices, from when both observers had coded"],
    [{ sliceMs: 2000, window: "steps", stepIds: ["s2", "s1"] }, "2 s slices, steps Story, Recall"],
    [{ sliceMs: 1000, window: "steps", stepIds: [] }, "1 s slices, steps (none chosen)"],
  ])("%j", (counted, words) => {
    expect(countedWords(counted, steps)).toBe(words);
  });
});

describe("whether two choices count the same", () => {
  const whole: Counted = { sliceMs: 1000, window: "trial", stepIds: [] };
  it.each<[string, Counted, boolean]>([
    ["the same, its keys in jsonb's order", JSON.parse('{"window":"trial","sliceMs":1000,"stepIds":[]}'), true],
    ["another slice", { ...whole, sliceMs: 500 }, false],
    ["another window", { ...whole, window: "bothCoding" }, false],
    ["steps chosen", { ...whole, stepIds: ["s1"] }, false],
  ])("%s", (_, other, same) => {
    expect(sameCount(whole, other)).toBe(same);
  });
  it("counts the same steps chosen in another order", () => {
    const steps: Counted = { sliceMs: 1000, window: "steps", stepIds: ["a", "b"] };
    expect(sameCount(steps, { ...steps, stepIds: ["b", "a"] })).toBe(true);
  });
});
