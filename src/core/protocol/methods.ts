// The methods text: a published version described in prose a paper can use
// (robot, steps in order, exact speech, what ran together, pauses, questions
// and where each answer led, time limits and where each led, loops, questionnaires,
// conditions, the version's hash).
// Written once against a style, so the Markdown and the plain text never differ
// in what they say.
import { type ActionNames, actionName, blockName } from "../designer/action-name";
import { INSTRUMENT_NAMES } from "../questionnaires/instruments";
import type { Instrument } from "../questionnaires/definition";
import type { StudySettings } from "../studies/settings";
import { loopsOf } from "../trial/loops";
import { answerOptions, branchTarget } from "../trial/protocol";
import { conditionWords } from "../plugins/senses";
import type { RobotEvent } from "../plugins/types";
import type { DesignAction, ProtocolSnapshot, TimeLimit } from "./document";
import { type AwaitedEvent, awaitedEvents, exitBy, exitOf, timesWords } from "./flow";
import { inCondition, variedParts } from "./variants";

export interface MethodsInput {
  snapshot: ProtocolSnapshot;
  version: number;
  hash: string;
  /** The robot as its plugin names it, and the plugin's version (null when none was installed). */
  robot: { name: string; pluginVersion: string | null };
  /** The study's conditions; `experiment` names the experiment each runs. */
  conditions: Array<{ name: string; description: string; experiment: string }>;
  /** `stratifiedBy` is the label of the question whose answers are the strata. */
  assignment: Pick<StudySettings["assignment"], "strategy" | "perCondition"> & { stratifiedBy?: string };
  /** Questionnaires given around the trial (those not attached are left out by the caller). */
  questionnaires: Array<{ name: string; timing: "before" | "after"; items: number; instrument: Instrument | null }>;
  /** What to call action types: the robot's library (action-name.ts). */
  names?: ActionNames;
  /** What the robot senses, as its plugin declares it: a wait names each event it waited for and its condition. */
  events?: RobotEvent[];
}

export interface Style {
  heading: (text: string) => string;
  strong: (text: string) => string;
  code: (text: string) => string;
  /** The researcher's own words, as they are. */
  text: (text: string) => string;
}

// Researchers' words may hold characters Markdown would read as formatting.
const escapeMarkdown = (s: string) => s.replace(/[\\`*_[\]<>#|~]/g, (c) => `\\${c}`);

export const MARKDOWN: Style = {
  heading: (t) => `## ${t}`,
  strong: (t) => `**${escapeMarkdown(t)}**`,
  code: (t) => `\`${t}\``,
  text: escapeMarkdown,
};

// Plain text is the same words: a heading keeps its own line and the
// researcher's capitals, to be styled where it is pasted.
export const PLAIN: Style = { heading: (t) => t, strong: (t) => t, code: (t) => t, text: (t) => t };

export function methodsMarkdown(input: MethodsInput): string {
  return methods(input, MARKDOWN);
}

export function methodsPlainText(input: MethodsInput): string {
  return methods(input, PLAIN);
}

export const quote = (s: Style, words: string) => `“${s.text(words.replace(/\s+/g, " ").trim())}”`;
// A sentence (or a step's name) that already ends on a full stop, or on quoted speech that does, takes no second one.
const stop = (t: string) => (/[.!?…]”?$/.test(t) ? t : `${t}.`);
const capital = (t: string) => t.charAt(0).toUpperCase() + t.slice(1);
export const plural = (n: number, one: string, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;
const seconds = (n: number) => (n === 1 ? "1 second" : `${n} seconds`);
const COUNTS = [
  "no",
  "one",
  "two",
  "three",
  "four",
  "five",
  "six",
  "seven",
  "eight",
  "nine",
  "ten",
  "eleven",
  "twelve",
];

function methods(input: MethodsInput, s: Style): string {
  const { snapshot } = input;
  const name = snapshot.experiment.name;
  const plugin = input.robot.pluginVersion ? `, plugin ${input.robot.pluginVersion}` : "";
  const sections = [
    `${s.heading(`Methods: ${s.text(name)}, version ${input.version}`)}`,
    [
      `The robot (${s.text(input.robot.name)}${plugin}) was operated by a wizard in HRIStudio, following version ${input.version} of the experiment ${quote(s, name)}.`,
      snapshot.experiment.description.trim() ? s.text(snapshot.experiment.description.trim()) : "",
      "The wizard started each action in the order below; actions described as happening at the same time started together.",
    ]
      .filter(Boolean)
      .join(" "),
    s.heading("Procedure"),
    procedure(input, s),
    ...loops(input.snapshot, s),
    ...variations(input, s),
    s.heading("Questionnaires"),
    questionnaires(input, s),
    s.heading("Conditions and assignment"),
    conditions(input, s),
    s.heading("Version"),
    `This description was generated from version ${input.version} of ${quote(s, name)}. The version's SHA-256 hash is ${s.code(input.hash)}.`,
  ];
  return `${sections.join("\n\n")}\n`;
}

type Steps = ProtocolSnapshot["steps"];
type Described = Pick<MethodsInput, "snapshot" | "names" | "events">;

function stepName(s: Style, steps: Steps, index: number): string {
  return quote(s, steps[index]!.name);
}

/** The Loops section, when the protocol has any: a sentence per loop. */
function loops(snapshot: ProtocolSnapshot, s: Style): string[] {
  const sentences = loopSentences(snapshot, s);
  return sentences.length ? [s.heading("Loops"), sentences.join(" ")] : [];
}

/** Each loop in a sentence: what made it go back, to which step, at most how often, and where the trial went on. */
export function loopSentences(snapshot: Pick<ProtocolSnapshot, "steps">, s: Style): string[] {
  const { steps } = snapshot;
  return loopsOf(snapshot).map(({ stepId, loop, seconds: limit }) => {
    const index = steps.findIndex((step) => step.id === stepId);
    const back = steps.findIndex((step) => step.id === loop.stepId);
    const when =
      limit === undefined
        ? `After ${stepName(s, steps, index)}`
        : `When the time limit of ${seconds(limit)} in ${stepName(s, steps, index)} ran out`;
    const onward = exitBy(steps, index, loop.onward);
    const then = onward.to === "step" ? `then continued to ${stepName(s, steps, onward.index)}` : "then ended";
    const to = back < 0 ? "a step that is no longer in the experiment" : stepName(s, steps, back);
    return `${when}, the trial went back to ${to}, at most ${timesWords(loop.times)}, and ${then}.`;
  });
}

/** Each step as a numbered paragraph: what happened, in order, and where it led. */
function procedure(input: MethodsInput, s: Style): string {
  const { steps } = input.snapshot;
  return [`The protocol had ${plural(steps.length, "step")}.`, stepParagraphs(input, s).join("\n")].join("\n\n");
}

/** Each condition's variants, as the lines of its protocol that differ from the procedure above; none when nothing varies. */
function variations(input: MethodsInput, s: Style): string[] {
  const varied = [...new Set(variedParts(input.snapshot.steps).flatMap((part) => part.conditions))];
  if (!varied.length) return [];
  const shared = new Set(stepParagraphs(input, s));
  const differing = varied.map((condition) => {
    const own = stepParagraphs({ ...input, snapshot: inCondition(input.snapshot, condition) }, s);
    return `${s.strong(`In ${condition}`)}\n${own.filter((line) => !shared.has(line)).join("\n")}`;
  });
  return [
    `Some actions differed by condition. These steps ran as follows in each condition named (numbered as above); every other condition ran the procedure above:\n\n${differing.join("\n\n")}`,
  ];
}

/** The steps' paragraphs, numbered: the lines two conditions' protocols are compared by. */
export function stepParagraphs(input: Described, s: Style): string[] {
  const { steps } = input.snapshot;
  const branchTargets = new Set<number>();
  for (const step of steps)
    for (const action of step.actions)
      if (action.type === "branch")
        for (const t of Object.values((action.parameters.targets ?? {}) as Record<string, unknown>)) {
          const at = steps.findIndex((x) => x.id === t);
          if (at >= 0) branchTargets.add(at);
        }
  return steps.map((step, index) => {
    const sentences = stepSentences(input, s, index);
    const ended = sentences.ended;
    // A loop is told in its own section, with its bound and where the trial went on.
    if (!ended && step.after?.to !== "again") {
      const exit = exitOf(steps, index);
      if (exit.to === "end") sentences.text.push("The trial then ended.");
      else if (exit.to === "missing") sentences.text.push("It then led to a step that is no longer in the experiment.");
      else if (exit.index !== index + 1 || branchTargets.has(index))
        sentences.text.push(`The trial then continued to ${stepName(s, steps, exit.index)}.`);
    }
    if (step.timeLimit)
      sentences.text.push(`${timeLimit(s, steps, index, step.timeLimit, "If the step had not ended within")}.`);
    const description = step.description.trim() ? ` ${s.text(step.description.trim())}` : "";
    const body = sentences.text.length ? sentences.text.join(" ") : "Nothing was carried out in this step.";
    return `${index + 1}. ${s.strong(stop(step.name.trim()))}${description} ${body}`;
  });
}

/** The sentences of one step; `ended` when the step leaves by itself (a question routing every answer, or "End trial"). */
function stepSentences(input: Described, s: Style, index: number): { text: string[]; ended: boolean } {
  const { steps } = input.snapshot;
  const actions = steps[index]!.actions;
  const text: string[] = [];
  let first = true;
  for (let a = 0; a < actions.length; a++) {
    const action = actions[a]!;
    if (action.type === "end_trial") {
      text.push("The trial ended here.");
      return { text, ended: true };
    }
    if (action.type === "record_answer") {
      const branch = actions[a + 1]?.type === "branch" ? actions[a + 1]! : null;
      const question = questionSentences(input, s, action, branch);
      text.push(...question.text);
      if (action.timeLimit)
        text.push(`${timeLimit(s, steps, index, action.timeLimit, "If no answer was recorded within")}.`);
      if (branch) a++;
      if (question.ended) return { text, ended: true };
      first = false;
      continue;
    }
    if (action.type === "branch") continue; // a branch with no question before it routes nothing
    if (action.type === "wait_for") {
      text.push(waitSentence(input, s, index, action, first));
      first = false;
      continue;
    }
    // A unit: this action and the ones right after it that share its parallel group.
    const unit = [action];
    while (action.parallelGroup && actions[a + 1]?.parallelGroup === action.parallelGroup) unit.push(actions[++a]!);
    const [lead, ...together] = unit.map((u) => clause(input, s, u));
    const rest = together.map((c) => (c.subject === lead!.subject && c.subject ? `it ${c.verb}` : c.full));
    const sentence = [lead!.full, ...rest].join(" at the same time as ");
    text.push(stop(first ? capital(sentence) : `Then ${sentence}`));
    first = false;
  }
  return { text, ended: false };
}

/** "If … within 20 seconds, the trial went on to “Prompt”": a time limit and where it led when the time ran out. */
function timeLimit(s: Style, steps: Steps, index: number, limit: TimeLimit, condition: string): string {
  const exit = exitBy(steps, index, limit.after);
  const then =
    exit.to === "end"
      ? "the trial ended"
      : exit.to === "missing"
        ? "the trial went on to a step that is no longer in the experiment"
        : limit.after.to === "again"
          ? `the trial went back to ${stepName(s, steps, exit.index)}, as the loops below say`
          : `the trial went on to ${stepName(s, steps, exit.index)}`;
  return `${condition} ${seconds(limit.seconds)}, ${then}`;
}

interface Clause {
  subject: string;
  verb: string;
  full: string;
}

function clause(input: Described, s: Style, action: DesignAction): Clause {
  const p = action.parameters;
  const make = (subject: string, verb: string): Clause => ({
    subject,
    verb,
    full: subject ? `${subject} ${verb}` : verb,
  });
  if (action.type === "pause") {
    const n = Number(p.seconds);
    return make("", Number.isFinite(n) ? `there was a pause of ${seconds(n)}` : "there was a pause");
  }
  if (action.type === "play_audio") {
    // The file by its name and hash: the exact sound, which a reader can ask for.
    const hash = typeof p.sha256 === "string" ? ` (SHA-256 ${s.code(p.sha256)})` : "";
    return make("", `the sound file ${quote(s, String(p.name ?? ""))}${hash} was played`);
  }
  if (action.type === "wizard_instruction")
    return make("the wizard", `followed the instruction ${quote(s, String(p.text ?? ""))}`);
  if (typeof p.text === "string" && p.text.trim()) return make("the robot", `said ${quote(s, p.text)}`);
  const label = actionName(action, input.names);
  const block = blockName(action.type, input.names);
  const kind = action.name?.trim() && block !== label ? ` (${s.text(block)})` : "";
  return make("the robot", `performed ${quote(s, label)}${kind}`);
}

/** A question the wizard answered, and where each answer led; rejoining answers are said once. */
function questionSentences(
  input: Described,
  s: Style,
  question: DesignAction,
  branch: DesignAction | null,
): { text: string[]; ended: boolean } {
  const { steps } = input.snapshot;
  const options = answerOptions(question);
  const prompt = typeof question.parameters.prompt === "string" ? question.parameters.prompt.trim() : "";
  const asked = `The wizard recorded the participant's answer${prompt ? ` to ${quote(s, prompt)}` : ""}`;
  const targets = options.map((o) => {
    const id = branch ? branchTarget(branch, o.id) : null;
    const at = id ? steps.findIndex((x) => x.id === id) : -1;
    return at >= 0 ? at : null;
  });
  if (!branch)
    return { text: [`${asked} as one of ${options.map((o) => quote(s, o.label)).join(", ")}.`], ended: false };
  const arms = options.map((o, i) => {
    const to = targets[i] ?? null;
    return `${quote(s, o.label)} led to ${to === null ? "the rest of this step" : stepName(s, steps, to)}`;
  });
  const text = [`${asked}: ${arms.join("; ")}.`];
  const routed = targets.filter((t): t is number => t !== null);
  const everyRouted = options.length > 0 && routed.length === options.length;
  // Answers whose steps all lead on to one step rejoin there.
  const joining = [...new Set(routed)];
  if (everyRouted && joining.length >= 2) {
    const exits = joining.map((t) => exitOf(steps, t));
    const joined = exits[0]!;
    const same = exits.every(
      (e) => e.to === joined.to && (e.to !== "step" || (joined.to === "step" && e.index === joined.index)),
    );
    if (same && joined.to === "step" && !joining.includes(joined.index)) {
      const all = options.length === 2 ? "Both answers" : `All ${COUNTS[options.length] ?? options.length} answers`;
      text.push(`${all} then continued to ${stepName(s, steps, joined.index)}.`);
    }
  }
  return { text, ended: everyRouted };
}

/** An event the robot senses in a paper's words: its name, what it is, and its condition as the plugin declares it. */
export function eventWords(s: Style, id: string, events: RobotEvent[] | undefined): string {
  const declared = events?.find((e) => e.id === id);
  if (!declared) return quote(s, id);
  const what = declared.description?.trim() ? `${s.text(declared.description.trim())}; ` : "";
  return `${quote(s, declared.name)} (${what}${conditionWords(declared.when)})`;
}

/** A wait: each event it waited for and where it led, its time limit, and the wizard's go on. */
function waitSentence(input: Described, s: Style, index: number, wait: DesignAction, first: boolean): string {
  const { steps } = input.snapshot;
  const led = (after: AwaitedEvent["after"]) => {
    const exit = exitBy(steps, index, after);
    return exit.to === "step" ? `led to ${stepName(s, steps, exit.index)}` : "ended the trial";
  };
  const events = awaitedEvents(wait).map((e) => `${eventWords(s, e.event, input.events)}, which ${led(e.after)}`);
  const limit = wait.timeLimit
    ? `if nothing was sensed within ${seconds(wait.timeLimit.seconds)}, the trial ${led(wait.timeLimit.after)}`
    : "";
  const waited = events.length ? `the trial waited for the robot to sense ${events.join(", or ")}` : "";
  const sentence = [waited, limit].filter(Boolean).join("; ");
  return `${stop(first ? capital(sentence) : `Then ${sentence}`)} The wizard could also go on without it.`;
}

function questionnaires(input: MethodsInput, s: Style): string {
  if (!input.questionnaires.length) return "No questionnaires were given with the trial.";
  return (["before", "after"] as const)
    .flatMap((timing) => {
      const given = input.questionnaires.filter((q) => q.timing === timing);
      if (!given.length) return [];
      const list = given.map((q) => {
        const instrument =
          q.instrument && INSTRUMENT_NAMES[q.instrument] !== q.name ? `, the ${INSTRUMENT_NAMES[q.instrument]}` : "";
        return `${quote(s, q.name)} (${plural(q.items, "item")}${instrument})`;
      });
      return [`${timing === "before" ? "Before" : "After"} the trial, participants completed ${joinAnd(list)}.`];
    })
    .join(" ");
}

export function joinAnd(items: string[]): string {
  return items.length <= 1 ? (items[0] ?? "") : `${items.slice(0, -1).join(", ")} and ${items.at(-1)}`;
}

function conditions(input: MethodsInput, s: Style): string {
  const list = input.conditions;
  if (!list.length) return "The study had no separate conditions: every participant followed this protocol.";
  const named = list.map(
    (c) =>
      `${quote(s, c.name)} (experiment ${quote(s, c.experiment)}${c.description.trim() ? `: ${s.text(c.description.trim())}` : ""})`,
  );
  const intro = `The study had ${plural(list.length, "condition")}: ${joinAnd(named)}.`;
  const { strategy, perCondition, stratifiedBy } = input.assignment;
  const blocks = `shuffled blocks holding each condition ${perCondition === 1 ? "once" : `${perCondition} times`}`;
  const how = {
    fixed: "The researcher assigned each participant to a condition.",
    random:
      "HRIStudio assigned each participant to a condition at random, from a seed stored with the study, so the assignment can be reproduced.",
    balanced: `HRIStudio assigned participants in ${blocks}, so group sizes differed by at most one block; the shuffle's seed is stored with the study.`,
    stratified: `HRIStudio assigned participants stratified by ${s.text(stratifiedBy ?? "a demographic question")}: within each answer, in ${blocks}, so each group's sizes differed by at most one block; the shuffle's seed is stored with the study.`,
    counterbalanced:
      "Each participant took part in every condition, in an order given by a balanced Latin square (Williams design).",
  }[strategy];
  return `${intro} ${how}`;
}
