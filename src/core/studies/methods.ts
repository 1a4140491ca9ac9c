// The study's methods text: the whole study described for a paper from its
// data as it stands (design, conditions and how their protocols differ, who
// took part, assignment, blinding, the robots the trials really ran on,
// measured step timings, questionnaires, coding agreement, fidelity, the
// software). Each section is a row of SECTIONS: a later feature of the study
// (timers, loops, robot events) is described by adding one row.
import type { Spread } from "../analysis/study-summary";
import type { ActionNames } from "../designer/action-name";
import type { ProtocolSnapshot } from "../protocol/document";
import type { RobotEvent } from "../plugins/types";
import { awaitedEvents } from "../protocol/flow";
import {
  eventWords,
  joinAnd,
  loopSentences,
  MARKDOWN,
  PLAIN,
  plural,
  quote,
  type Style,
  stepParagraphs,
} from "../protocol/methods";
import { inCondition } from "../protocol/variants";
import type { Instrument } from "../questionnaires/definition";
import type { StudySettings } from "./settings";

export interface ConditionFacts {
  name: string;
  description: string;
  experiment: string;
  /** The experiment's latest published version, what to call the robot's actions (its plugin's library) and what the robot senses. */
  protocol: {
    version: number;
    hash: string;
    snapshot: ProtocolSnapshot;
    names?: ActionNames;
    events?: RobotEvent[];
  } | null;
  /** Participants assigned to it (within subjects: every participant whose order holds it). */
  enrolled: number;
  /** Of those, how many finished a trial of it; withdrew; and were left out, by reason. */
  completed: number;
  withdrawn: number;
  excluded: Array<{ reason: string; n: number }>;
  /** Each step's time across this condition's finished trials, in protocol order. */
  steps: Array<{ name: string; durationMs: Spread | null }>;
  fidelity: {
    trials: number;
    meanFidelity: number | null;
    sdFidelity: number | null;
    withoutDeviation: number;
    deviationsByKind: Record<string, number>;
  };
}

export interface StudyFacts {
  title: string;
  conditions: ConditionFacts[];
  assignment: Pick<StudySettings["assignment"], "strategy" | "perCondition"> & {
    seed: string | null;
    /** The label of the question whose answers are the strata. */
    stratifiedBy?: string;
  };
  blinding: StudySettings["blinding"];
  /** Each robot the study's trials ran on, with the plugin document they ran with, and how many trials. */
  robots: Array<{
    name: string;
    /** Null when the trial kept no robot record (a trial from before robots were registered). */
    simulated: boolean | null;
    plugin: string;
    pluginVersion: string | null;
    pluginHash: string | null;
    trials: number;
  }>;
  questionnaires: Array<{
    name: string;
    timing: "before" | "after";
    items: number;
    instrument: Instrument | null;
    responses: number;
  }>;
  /** Each coding scheme at its latest version; kappa per set for each pair of observers, pooled over the trials both coded. */
  coding: Array<{
    name: string;
    version: number;
    /** What the kappa counted, in words (`countedWords`): the slice and the window the scheme keeps. */
    counted: string;
    sets: Array<{ name: string; pairs: Array<{ observers: [string, string]; kappa: number | null; slices: number }> }>;
  }>;
  software: { version: string };
}

/** How each instrument is scored, and the reference a paper cites for it. */
export const SCORING: Record<Instrument, string> = {
  sus: "scored as published: odd items (answer − 1), even items (5 − answer), the sum × 2.5, giving 0–100 (Brooke, 1996, “SUS: A ‘quick and dirty’ usability scale”, in Usability Evaluation in Industry, pp. 189–194)",
  godspeed:
    "scored as published: the mean of each sub-scale's items (anthropomorphism, animacy, likeability, perceived intelligence, perceived safety); the published instrument defines no overall score (Bartneck, Kulić, Croft & Zoghbi, 2009, International Journal of Social Robotics 1(1), 71–81)",
};

/** A deviation kind (src/core/trial/types.ts) in a paper's words, with its count. */
export const DEVIATION_WORDS: Record<string, (n: number) => string> = {
  skipped: (n) => `${plural(n, "action")} skipped`,
  out_of_order: (n) => `${plural(n, "action")} run out of order`,
  unscripted: (n) => `${plural(n, "unscripted action")}`,
  manual_jump: (n) => `${plural(n, "jump")} to another step by hand`,
  ended_early: (n) => `${plural(n, "trial")} ended early`,
};

interface Section {
  heading: string;
  /** The section's paragraphs; empty leaves the section out. */
  write: (facts: StudyFacts, s: Style) => string[];
}

const number = (ms: number) => (ms / 1000).toFixed(1);
const seconds = (ms: number) => `${number(ms)} s`;
const percent = (x: number) => `${x.toFixed(1)}%`;

const SECTIONS: Section[] = [
  { heading: "Design", write: design },
  { heading: "Participants", write: participants },
  { heading: "Assignment", write: assignment },
  { heading: "Blinding", write: blinding },
  { heading: "Robots", write: robots },
  { heading: "Protocol", write: protocol },
  { heading: "Loops", write: loops },
  { heading: "Robot senses", write: senses },
  { heading: "Step timings", write: timings },
  { heading: "Questionnaires", write: questionnaires },
  { heading: "Coding and agreement", write: coding },
  { heading: "Fidelity and deviations", write: fidelity },
  { heading: "Software", write: software },
];

export function studyMethodsMarkdown(facts: StudyFacts): string {
  return studyMethods(facts, MARKDOWN);
}

export function studyMethodsPlainText(facts: StudyFacts): string {
  return studyMethods(facts, PLAIN);
}

function studyMethods(facts: StudyFacts, s: Style): string {
  const parts = [s.heading(`Methods: ${s.text(facts.title)}`)];
  for (const section of SECTIONS) {
    const paragraphs = section.write(facts, s);
    if (paragraphs.length) parts.push(s.heading(section.heading), ...paragraphs);
  }
  return `${parts.join("\n\n")}\n`;
}

const within = (f: StudyFacts) => f.assignment.strategy === "counterbalanced";

function design(f: StudyFacts, s: Style): string[] {
  const list = f.conditions;
  if (list.length < 2)
    return [
      list.length
        ? `The study had one condition, ${quote(s, list[0]!.name)}: every participant followed the same protocol.`
        : "The study had no conditions: every participant followed the same protocol.",
    ];
  const named = list.map(
    (c) =>
      `${quote(s, c.name)} (experiment ${quote(s, c.experiment)}${c.description.trim() ? `: ${s.text(c.description.trim())}` : ""})`,
  );
  const kind = within(f)
    ? "within-subjects design: each participant took part in every condition"
    : "between-subjects design: each participant took part in one condition";
  return [`The study had a ${kind}. It had ${plural(list.length, "condition")}: ${joinAnd(named)}.`];
}

function participants(f: StudyFacts, s: Style): string[] {
  return f.conditions.map((c) => {
    const excluded = c.excluded.filter((e) => e.n > 0);
    const left = excluded.length
      ? `; ${excluded.reduce((n, e) => n + e.n, 0)} excluded (${joinAnd(excluded.map((e) => `${e.n} ${e.reason}`))})`
      : "; none excluded";
    return `${quote(s, c.name)}: ${c.enrolled} enrolled, ${c.completed} completed, ${c.withdrawn} withdrew${left}.`;
  });
}

function assignment(f: StudyFacts, s: Style): string[] {
  if (f.conditions.length < 2) return [];
  const { strategy, perCondition, stratifiedBy, seed } = f.assignment;
  const blocks = `shuffled blocks holding each condition ${perCondition === 1 ? "once" : `${perCondition} times`}`;
  const how = {
    fixed: "The researcher assigned each participant to a condition.",
    random: "HRIStudio assigned each participant to a condition at random.",
    balanced: `HRIStudio assigned participants in ${blocks}, so group sizes differed by at most one block.`,
    stratified: `HRIStudio assigned participants stratified by ${s.text(stratifiedBy ?? "a demographic question")}: within each answer, in ${blocks}.`,
    counterbalanced: "The order of conditions was given by a balanced Latin square (Williams design).",
  }[strategy];
  const reproduce =
    strategy !== "fixed" && seed ? ` The assignment's seed was ${s.code(seed)}, from which it can be reproduced.` : "";
  return [`${how}${reproduce}`];
}

function blinding(f: StudyFacts): string[] {
  const wizards = f.blinding.conditionsFromWizards
    ? "Wizards were blind to condition: HRIStudio showed them neither the condition nor the experiment's name."
    : "Wizards were not blind to condition.";
  const results = f.blinding.resultsUntilComplete
    ? "Researchers and observers saw no results until the study was marked completed."
    : "Researchers and observers could see results while the study ran.";
  const observers = f.blinding.conditionsFromObservers
    ? "Observers and coders were blind to condition: HRIStudio showed them neither the condition nor any result."
    : "Observers and coders were not blind to condition.";
  return [`${wizards} ${results} ${observers}`];
}

function robots(f: StudyFacts, s: Style): string[] {
  if (!f.robots.length) return ["No trial has run on a robot yet."];
  return [
    `The trials ran on ${joinAnd(
      f.robots.map((r) => {
        const plugin = [
          r.pluginVersion ? `version ${r.pluginVersion}` : "",
          r.pluginHash ? `SHA-256 ${s.code(r.pluginHash)}` : "",
        ]
          .filter(Boolean)
          .join(", ");
        return `${quote(s, r.name)} (${r.simulated === null ? "simulated or physical not recorded" : r.simulated ? "simulated" : "physical"}; plugin ${quote(s, r.plugin)}${plugin ? `, ${plugin}` : ""}; ${plural(r.trials, "trial")})`;
      }),
    )}.`,
  ];
}

/** Each condition's protocol in full when there is one; with several, the steps they share once and what differs by condition. */
/** The events of the robot's senses each condition's protocol waited for, with their conditions; none leaves the section out. */
function senses(f: StudyFacts, s: Style): string[] {
  return f.conditions.flatMap((c) => {
    const steps = c.protocol?.snapshot.steps ?? [];
    const waited = steps.flatMap((step) =>
      step.actions.flatMap((a) => awaitedEvents(a).map((e) => ({ event: e.event, step: step.name }))),
    );
    if (!waited.length) return [];
    const ids = [...new Set(waited.map((w) => w.event))];
    const listed = ids.map((id) => {
      const where = [...new Set(waited.filter((w) => w.event === id).map((w) => quote(s, w.step)))];
      return `${eventWords(s, id, c.protocol!.events)} in ${joinAnd(where)}`;
    });
    return [
      `In ${quote(s, c.name)}, the trial waited for the robot to sense ${joinAnd(listed)}; the wizard could go on without it.`,
    ];
  });
}

function protocol(f: StudyFacts, s: Style): string[] {
  const described = f.conditions.filter((c) => c.protocol);
  // Each condition's protocol as it runs it: conditions of one experiment differ in their variants.
  const lines = (c: ConditionFacts) =>
    stepParagraphs({ ...c.protocol!, snapshot: inCondition(c.protocol!.snapshot, c.name) }, s);
  const versionOf = (c: ConditionFacts) =>
    `${quote(s, c.name)} ran version ${c.protocol!.version} of ${quote(s, c.experiment)} (SHA-256 ${s.code(c.protocol!.hash)})`;
  if (!described.length) return ["No condition's experiment has been published yet."];
  const unpublished = f.conditions.filter((c) => !c.protocol).map((c) => quote(s, c.name));
  const note = unpublished.length ? [`${joinAnd(unpublished)}: its experiment has not been published yet.`] : [];
  if (described.length === 1) return [`${versionOf(described[0]!)}.`, lines(described[0]!).join("\n"), ...note];
  // A step paragraph without its number: a step added before it moves the number, not the step.
  const body = (line: string) => line.replace(/^\d+\.\s/, "");
  const shared = lines(described[0]!).filter((l) => described.every((c) => lines(c).some((m) => body(m) === body(l))));
  const sharedBodies = new Set(shared.map(body));
  const differing = described.map((c) => {
    const own = lines(c).filter((l) => !sharedBodies.has(body(l)));
    return `${s.strong(`Only in ${c.name}`)}\n${own.length ? own.join("\n") : "(nothing of its own)"}`;
  });
  return [
    `${joinAnd(described.map(versionOf))}.`,
    shared.length
      ? `The conditions shared these steps (numbered as in ${quote(s, described[0]!.name)}):\n${shared.join("\n")}`
      : "The conditions shared no step.",
    `They differed in these steps (numbered as in each condition's own protocol):\n\n${differing.join("\n\n")}`,
    ...note,
  ];
}

/** Each condition's loops, said once when the conditions' protocols loop alike. */
function loops(f: StudyFacts, s: Style): string[] {
  const told = f.conditions.flatMap((c) =>
    c.protocol ? [{ name: c.name, text: loopSentences(c.protocol.snapshot, s).join(" ") }] : [],
  );
  const looping = told.filter((t) => t.text);
  if (!looping.length) return [];
  if (looping.length === told.length && looping.every((t) => t.text === looping[0]!.text)) return [looping[0]!.text];
  return looping.map((t) => `In ${quote(s, t.name)}: ${t.text}`);
}

function timings(f: StudyFacts, s: Style): string[] {
  return f.conditions.flatMap((c) => {
    const timed = c.steps.filter((st) => st.durationMs);
    if (!timed.length) return [];
    const each = timed.map(({ name, durationMs: d }) => {
      const range = d!.min !== d!.max ? `, range ${number(d!.min)}–${seconds(d!.max)}` : "";
      return `${quote(s, name)} median ${seconds(d!.median)}${range} (n = ${d!.n})`;
    });
    return [`In ${quote(s, c.name)}, measured from the trials' logs: ${each.join("; ")}.`];
  });
}

function questionnaires(f: StudyFacts, s: Style): string[] {
  if (!f.questionnaires.length) return ["No questionnaires were given with the trials."];
  return f.questionnaires.map((q) => {
    const scored = q.instrument ? `, ${SCORING[q.instrument]}` : "";
    return `${q.timing === "before" ? "Before" : "After"} the trial: ${quote(s, q.name)} (${plural(q.items, "item")}; ${plural(q.responses, "response")})${scored}.`;
  });
}

function coding(f: StudyFacts, s: Style): string[] {
  if (!f.coding.length) return [];
  return f.coding.map((scheme) => {
    const sets = scheme.sets.map((set) => {
      if (!set.pairs.length) return `${quote(s, set.name)}: no trial was coded by two observers`;
      const pairs = set.pairs.map(
        (p) =>
          `Cohen's κ = ${p.kappa === null ? "undefined" : p.kappa.toFixed(2)} between ${s.text(p.observers[0])} and ${s.text(p.observers[1])} (${plural(p.slices, "slice")})`,
      );
      return `${quote(s, set.name)}: ${joinAnd(pairs)}`;
    });
    return `Observers coded with ${quote(s, scheme.name)} (version ${scheme.version}); agreement was counted in ${scheme.counted}: ${sets.join("; ")}.`;
  });
}

function fidelity(f: StudyFacts, s: Style): string[] {
  return f.conditions.map(({ name, fidelity: x }) => {
    if (!x.trials) return `${quote(s, name)}: no trial has finished.`;
    const sd = x.sdFidelity === null ? "" : ` (SD ${x.sdFidelity.toFixed(1)})`;
    const kinds = Object.entries(x.deviationsByKind).filter(([, n]) => n > 0);
    const deviations = kinds.length
      ? `; deviations: ${joinAnd(kinds.map(([kind, n]) => DEVIATION_WORDS[kind]?.(n) ?? `${n} ${kind}`))}`
      : "; no deviations";
    return `${quote(s, name)}: mean execution fidelity ${percent(x.meanFidelity!)}${sd} over ${plural(x.trials, "trial")}; ${x.withoutDeviation} of ${x.trials} without any deviation${deviations}.`;
  });
}

function software(f: StudyFacts): string[] {
  return [`The study was run and this text generated with HRIStudio ${f.software.version}.`];
}
