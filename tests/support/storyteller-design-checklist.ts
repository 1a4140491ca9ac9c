// The "design" checklist of the project brief's protocol document (interactive-storyteller.md),
// scored by code from an exported experiment file (src/core/designer/exchange.ts).
import { STORYTELLER_TEXT as TEXT } from "./storyteller-run-checklist";

interface FileAction {
  type: string;
  parameters: Record<string, unknown>;
  runTogether?: string;
}
interface FileStep {
  key: string;
  name: string;
  actions: FileAction[];
}

const GESTURES = ["wave", "nod", "head_shake", "look_down", "pause", "play_animation", "posture"];
const isA = (a: FileAction | undefined, word: string) =>
  !!a && (a.type === word || a.type.endsWith(`.${word}`) || a.type.includes(word));

export function scoreDesign(fileText: string) {
  const file = JSON.parse(fileText) as { steps: FileStep[] };
  const steps = file.steps;
  const stepWith = (text: string) =>
    steps.findIndex((s) => s.actions.some((a) => a.type === "say" && a.parameters.text === text));
  const [intro, story, question, correct, incorrect] = [
    TEXT.intro,
    TEXT.story,
    TEXT.question,
    TEXT.correct,
    TEXT.incorrect,
  ].map(stepWith) as [number, number, number, number, number];
  const inStep = (i: number, pick: (a: FileAction) => boolean) => steps[i]?.actions.filter(pick) ?? [];

  // The question's step records the answer and branches on it at once; each answer goes to its response.
  const questionStep = steps[question];
  const answerAt = questionStep?.actions.findIndex((a) => a.type === "record_answer") ?? -1;
  const answer = questionStep?.actions[answerAt];
  const branch = questionStep?.actions[answerAt + 1];
  const options = (answer?.parameters.options ?? []) as Array<{ id: string; label: string }>;
  const targets = (branch?.parameters.targets ?? {}) as Record<string, string>;
  const targetOf = (pattern: RegExp) => targets[options.find((o) => pattern.test(o.label))?.id ?? ""];
  const branchResolves =
    answerAt >= 0 &&
    branch?.type === "branch" &&
    options.length === 2 &&
    targetOf(/^correct/i) === `@${steps[correct]?.key}` &&
    targetOf(/^incorrect|know/i) === `@${steps[incorrect]?.key}`;

  const items: Array<[string, number, boolean]> = [
    ["intro speech with the exact text", 10, intro >= 0],
    ["story speech with the exact text", 10, story >= 0],
    ["question with the exact text", 10, question >= 0],
    ["both branch responses with the exact text", 10, correct >= 0 && incorrect >= 0],
    // A step is found by its speech; with the speech wrong, by its place, so one mistake costs one item.
    ["wave as a distinct action in step 1", 10, intro <= 0 && inStep(0, (a) => isA(a, "wave")).length > 0],
    [
      "a narrative gesture as a distinct action in step 2",
      10,
      (story === 1 || story < 0) && inStep(1, (a) => GESTURES.some((g) => isA(a, g))).length > 0,
    ],
    [
      "nod in branch A, head shake in branch B",
      10,
      inStep(correct, (a) => isA(a, "nod")).length > 0 && inStep(incorrect, (a) => isA(a, "head_shake")).length > 0,
    ],
    ["a branch that resolves from the recorded answer", 15, branchResolves],
    [
      "all four steps in the right order",
      15,
      intro <= 0 && story === 1 && question === 2 && Math.min(correct, incorrect) === 3,
    ],
  ];
  return {
    score: items.reduce((n, [, points, ok]) => n + (ok ? points : 0), 0),
    failed: items.filter(([, , ok]) => !ok).map(([name]) => name),
  };
}
