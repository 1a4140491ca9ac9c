// The experiment file: how a protocol leaves one HRIStudio and enters another
// (a lab sharing its study with another lab). Format version 4:
//
//   {
//     "format": "hristudio.experiment",
//     "formatVersion": 4,
//     "experiment": { "name": "…", "description": "…", "robot": "nao6-ros2" },
//     "steps": [
//       {
//         "key": "step-1",
//         "name": "…",
//         "description": "…",
//         "after": "@step-5",
//         "timeLimit": { "seconds": 30, "after": "end" },
//         "actions": [
//           { "type": "say", "name": "…", "parameters": { "text": "…" }, "runTogether": "group-1",
//             "variants": { "Warm tutor": { "parameters": { "text": "…" } } } }
//         ],
//         "variants": { "Warm tutor": { "actions": [ … ] } }
//       }
//     ]
//   }
//
// Database ids never leave: steps are keyed by position ("step-1"…), a branch
// names its targets by key ("@step-3"), a step's "after" is a key or "end" (left
// out for "the next step"; version 1 files have none), a time limit (version 3,
// on a step or a record_answer) is { "seconds": 10, "after": "@step-4" },
// its "after" written as a step's is, as is each event's of a "Wait for"
// (its parameters' events), a loop (version 4) is { "again": "@step-2",
// "times": 2, "onward": "end" } ("onward" written as an "after", left out for
// the next step), and run-together groups are renamed
// "group-1", "group-2"… in order of first appearance ("runTogether" is left out
// for an action that runs alone). Variants (version 4) are kept under their
// condition's name; a step's variant's actions are written as the step's are. The writer is deterministic (fixed key order,
// parameters sorted, 2-space indent, final newline) so an exported file diffs
// cleanly and exporting an imported export gives the same bytes.
//
// Import checks the file's shape, not its actions: the imported draft goes
// through validateDesign like any other, against whatever robot is at hand.
// The file is the experiment document (../protocol/document.ts) under other
// names: its types derive from the declaration, and its format version is the
// document's. A file of an earlier version is upgraded once checked
// (../protocol/versions.ts); a field a version added is refused in older files.
import type { z } from "zod";
import {
  type actionSchema,
  actionCountProblem,
  DESIGN_LIMITS,
  DOCUMENT_VERSION,
  type experimentFields,
  MAX_LOOP_TIMES,
  MAX_TIME_LIMIT_SECONDS,
  type Onward,
  type stepSchema,
} from "../protocol/document";
import { fieldsAfter, type FilePlace, READABLE_VERSIONS, upgradeFile } from "../protocol/versions";
import { finish, type Work } from "../work";
import { parsingFile } from "./file-parse";
import type { After, DesignAction, DesignDraft, DesignStep, NewId } from "./types";
import type { TimeLimit } from "../protocol/document";

const FORMAT = "hristudio.experiment";
const MAX_BYTES = 2 * 1024 * 1024;
const MAX_STEPS = DESIGN_LIMITS.steps;
const MAX_ACTIONS = DESIGN_LIMITS.actionsPerStep;
const MAX_NAME = DESIGN_LIMITS.name;
/** A description, and any text inside parameters. */
const MAX_TEXT = DESIGN_LIMITS.description;
const MAX_NOTE = DESIGN_LIMITS.note;
const MAX_DEPTH = 32;

/**
 * Each field of the document and its name in the file; null: left out (ids
 * never leave: a step is keyed by position). A field added to the declaration
 * does not compile until it is given its place here; the writer and the
 * reader then carry it as it is (give check() its rule, and the version that
 * brought it its fileFields in ../protocol/versions.ts).
 */
const EXPERIMENT_FIELDS = {
  name: "name",
  description: "description",
  robotId: "robot",
} as const satisfies Record<keyof z.input<typeof experimentFields>, string>;
const STEP_FIELDS = {
  id: "key",
  name: "name",
  description: "description",
  after: "after",
  timeLimit: "timeLimit",
  actions: "actions",
  variants: "variants",
} as const satisfies Record<keyof DesignStep, string>;
const ACTION_FIELDS = {
  id: null,
  type: "type",
  name: "name",
  parameters: "parameters",
  parallelGroup: "runTogether",
  note: "note",
  timeLimit: "timeLimit",
  variants: "variants",
} as const satisfies Record<keyof DesignAction, string | null>;

/** An action as the declaration reads it (defaults left out), with its run-together group named. The note is absent when there is none. */
type FileAction = Omit<z.input<typeof actionSchema>, "id" | "parallelGroup" | "timeLimit"> & {
  runTogether?: string;
  timeLimit?: FileTimeLimit;
};

/** "Go back to a step at most `times` times, then `onward`" ("@step-K" or "end"; absent for the next step). */
interface FileLoop {
  again: string;
  times: number;
  onward?: string;
}

/** Where a step (or a time limit) leads: "@step-K", "end", or a loop; absent for the next step. */
type FileAfter = string | FileLoop;

/** A time limit whose way on is written as a step's "after" is. */
interface FileTimeLimit {
  seconds: number;
  after?: FileAfter;
}

/** A step keyed "step-K"; "after" is "@step-K", "end" or a loop, absent for the next step. */
type FileStep = Omit<z.input<typeof stepSchema>, "id" | "after" | "actions" | "timeLimit" | "variants"> & {
  key: string;
  after?: FileAfter;
  timeLimit?: FileTimeLimit;
  actions: FileAction[];
  variants?: Record<string, { actions: FileAction[] }>;
};

export interface ExperimentFile {
  format: typeof FORMAT;
  formatVersion: typeof DOCUMENT_VERSION;
  experiment: Omit<z.input<typeof experimentFields>, "robotId"> & { robot: string };
  steps: FileStep[];
}

export interface ImportProblem {
  /** Where in the file, as a JSON path: $.steps[2].actions[0].type */
  path: string;
  message: string;
}

export type ImportResult = { ok: true; draft: DesignDraft } | { ok: false; problems: ImportProblem[] };

export function exportExperiment(draft: DesignDraft): string {
  const keys = new Map(draft.steps.map((step, i) => [step.id, `@step-${i + 1}`]));
  const groups = new Map<string, string>();
  const group = (id: string) => groups.get(id) ?? groups.set(id, `group-${groups.size + 1}`).get(id)!;
  // A target that is no step of the draft is already an error in the designer; an id would mean nothing elsewhere.
  const fileParameters = leadsRewritten(
    (id) => keys.get(id),
    (after) => fileAfter(after as After, keys),
  );
  const fileAction = (action: Omit<DesignAction, "variants"> & Pick<Partial<DesignAction>, "variants">) => ({
    ...toFile(action, ACTION_FIELDS),
    type: action.type,
    parameters: fileParameters(action.type, action.parameters),
    // A condition's variant may branch elsewhere, or be a branch where the action is not.
    variants: mapVariants(action.variants, (v) => ({
      ...v,
      parameters: fileParameters(v.type ?? action.type, v.parameters),
    })),
    runTogether: action.parallelGroup ? group(action.parallelGroup) : undefined,
    note: action.note || undefined,
    timeLimit: fileLimit(action.timeLimit, keys),
  });
  const file: ExperimentFile = {
    format: FORMAT,
    formatVersion: DOCUMENT_VERSION,
    experiment: { ...toFile(draft, EXPERIMENT_FIELDS), name: draft.name, robot: draft.robotId },
    steps: draft.steps.map((step, i) => ({
      ...toFile(step, STEP_FIELDS),
      key: `step-${i + 1}`,
      name: step.name,
      after: fileAfter(step.after, keys),
      timeLimit: fileLimit(step.timeLimit, keys),
      actions: step.actions.map(fileAction),
      variants: mapVariants(step.variants, (variant) => ({ actions: variant.actions.map(fileAction) })),
    })),
  };
  return `${write(file, "", false)}\n`;
}

/** Never throws: a file that cannot be imported comes back as its problems, each with its place in the file. */
export function importExperiment(text: string, newId: NewId): ImportResult {
  return finish(importing(text, newId));
}

/** importExperiment as work that yields after each step, for the server to run in slices. */
export function* importing(text: string, newId: NewId): Work<ImportResult> {
  const checked = yield* checking(text);
  if (!checked.ok) return checked;
  const { steps, ...experiment } = draftOf(checked.file, newId);
  const made: DesignStep[] = [];
  for (const step of steps) {
    made.push(step);
    yield;
  }
  return { ok: true, draft: { ...experiment, steps: made } };
}

export type CheckResult = { ok: true; file: ExperimentFile } | { ok: false; problems: ImportProblem[] };

/** The file read and its shape checked, as work that yields after each step, for the server to run in slices. */
export function* checking(text: string): Work<CheckResult> {
  if (text.length > MAX_BYTES || new TextEncoder().encode(text).length > MAX_BYTES) {
    return {
      ok: false,
      problems: [
        {
          path: "$",
          message: "the file is larger than 2 MB; an experiment file is far smaller, so this is probably not one",
        },
      ],
    };
  }
  const parsed = yield* parsingFile(text);
  if (!parsed.ok) {
    return {
      ok: false,
      problems: [
        { path: "$", message: `is not valid JSON: ${parsed.reason} (line ${parsed.line}, column ${parsed.column})` },
      ],
    };
  }
  // Counted before anything else is read: a file over the limit costs no more than its parse.
  const steps = isObject(parsed.value) && Array.isArray(parsed.value.steps) ? parsed.value.steps : [];
  const tooMany = actionCountProblem(steps);
  if (tooMany) return { ok: false, problems: [{ path: "$.steps", message: tooMany }] };
  const problems = yield* check(parsed.value);
  return problems.length
    ? { ok: false, problems }
    : { ok: true, file: upgradeFile<ExperimentFile>(parsed.value as Record<string, unknown>) };
}

/**
 * A checked file as a draft whose steps are made (with fresh ids) one at a
 * time as they are read: the server stores a large design as it is made,
 * never holding all 50,000 new actions at once.
 */
export function draftOf(
  file: ExperimentFile,
  newId: NewId,
): Omit<DesignDraft, "steps"> & { steps: Iterable<DesignStep> } {
  const ids = new Map(file.steps.map((step) => [`@${step.key}`, newId()]));
  const groups = new Map<string, string>();
  const group = (name: string) => groups.get(name) ?? groups.set(name, newId()).get(name)!;
  const draftParameters = leadsRewritten(
    (key) => ids.get(key),
    (after) => draftAfter(after as string | undefined, ids),
  );
  const draftAction = (action: FileAction): DesignAction => ({
    ...fromFile(action, ACTION_FIELDS),
    id: newId(),
    type: action.type,
    name: action.name ?? "",
    parameters: draftParameters(action.type, action.parameters ?? {}),
    variants: mapVariants(action.variants, (v) => ({
      ...v,
      parameters: draftParameters(v.type ?? action.type, v.parameters ?? {}),
    })),
    parallelGroup: action.runTogether === undefined ? null : group(action.runTogether),
    note: action.note || undefined,
    timeLimit: draftLimit(action.timeLimit, ids),
  });
  function* steps(): Generator<DesignStep, void, void> {
    for (const step of file.steps) {
      yield {
        ...fromFile(step, STEP_FIELDS),
        id: ids.get(`@${step.key}`)!,
        name: step.name,
        description: step.description ?? "",
        after: draftAfter(step.after, ids),
        timeLimit: draftLimit(step.timeLimit, ids),
        actions: step.actions.map(draftAction),
        variants: mapVariants(step.variants, (variant) => ({
          // A step's variant's actions are its own: they carry no variants inside.
          actions: variant.actions.map(({ variants: _, ...action }) => draftAction(action)),
        })),
      };
    }
  }
  return {
    ...fromFile(file.experiment, EXPERIMENT_FIELDS),
    name: file.experiment.name,
    description: file.experiment.description ?? "",
    robotId: file.experiment.robot,
    steps: steps(),
  };
}

/**
 * The document's fields under their file names, as they are: what the file
 * writes its own way (ids, where a step leads, groups, a branch's targets) is
 * set after, over them.
 */
function toFile(value: object, names: Readonly<Record<string, string | null>>): Record<string, unknown> {
  const fields = Object.entries(names).flatMap(([field, name]) =>
    name === null ? [] : [[name, (value as Record<string, unknown>)[field]] as const],
  );
  return Object.fromEntries(fields);
}

/** The file's fields under the document's names, as they are; the reader sets its own over them. */
function fromFile(value: object, names: Readonly<Record<string, string | null>>): Record<string, unknown> {
  const fields = Object.entries(names).flatMap(([field, name]) =>
    name === null ? [] : [[field, (value as Record<string, unknown>)[name]] as const],
  );
  return Object.fromEntries(fields);
}

/** Each condition's variant made anew; none stays none (left out of the file and the draft). */
function mapVariants<T, U>(variants: Record<string, T> | undefined, map: (variant: T) => U) {
  return variants && Object.fromEntries(Object.entries(variants).map(([condition, v]) => [condition, map(v)]));
}

function fileAfter(after: After | undefined, keys: Map<string, string>): FileAfter | undefined {
  if (after?.to === "again") {
    const again = keys.get(after.stepId);
    return again && { again, times: after.times, onward: fileAfter(after.onward, keys) as string | undefined };
  }
  if (after?.to === "end") return "end";
  // An after to a step that is gone is already an error in the designer; like a branch target, it is left out.
  return after?.to === "step" ? keys.get(after.stepId) : undefined;
}

function draftAfter(after: FileAfter | undefined, ids: Map<string, string>): After {
  if (typeof after === "object") {
    const stepId = ids.get(after.again);
    const onward = draftAfter(after.onward, ids) as Onward;
    return stepId ? { to: "again", stepId, times: after.times, onward } : onward;
  }
  if (after === "end") return { to: "end" };
  const stepId = after === undefined ? undefined : ids.get(after);
  return stepId ? { to: "step", stepId } : { to: "next" };
}

function fileLimit(limit: TimeLimit | undefined, keys: Map<string, string>): FileTimeLimit | undefined {
  return limit && { seconds: limit.seconds, after: fileAfter(limit.after, keys) };
}

function draftLimit(limit: FileTimeLimit | undefined, ids: Map<string, string>): TimeLimit | undefined {
  return limit && { seconds: limit.seconds, after: draftAfter(limit.after, ids) };
}

/**
 * An action's parameters with where they lead rewritten (a branch's targets, a wait's events' ways on), by the
 * type the action has where they are: its own, or the one a condition's variant gives it.
 */
function leadsRewritten(rename: (target: string) => string | undefined, rewrite: (after: unknown) => unknown) {
  return (type: string, parameters: Record<string, unknown>) =>
    type === "branch"
      ? swapTargets(parameters, rename)
      : type === "wait_for"
        ? swapWaitAfters(parameters, rewrite)
        : parameters;
}

/** A branch's targets renamed one by one; a target with no new name is dropped. */
function swapTargets(
  parameters: Record<string, unknown>,
  rename: (target: string) => string | undefined,
): Record<string, unknown> {
  if (!isObject(parameters.targets)) return parameters;
  const targets = Object.entries(parameters.targets).flatMap(([option, target]) => {
    const renamed = typeof target === "string" ? rename(target) : undefined;
    return renamed === undefined ? [] : [[option, renamed] as const];
  });
  // fromEntries and spread define properties, so a key like "__proto__" stays data.
  return { ...parameters, targets: Object.fromEntries(targets) };
}

/** A wait's events with where each leads rewritten (a draft's After ⇄ a file's "@step-K", "end" or nothing). */
function swapWaitAfters(
  parameters: Record<string, unknown>,
  rewrite: (after: unknown) => unknown,
): Record<string, unknown> {
  if (!Array.isArray(parameters.events)) return parameters;
  const events = parameters.events.map((event: unknown) => {
    if (!isObject(event)) return event;
    const { after, ...rest } = event;
    const rewritten = rewrite(after);
    return rewritten === undefined ? rest : { ...rest, after: rewritten };
  });
  return { ...parameters, events };
}

// By hand because JSON.stringify puts integer-like keys ("2", "10") first
// whatever the insertion order, and parameters must come out sorted.
function write(value: unknown, indent: string, sorted: boolean): string {
  const inner = `${indent}  `;
  if (Array.isArray(value)) {
    if (value.length === 0) return "[]";
    return `[\n${value.map((v) => inner + write(v, inner, sorted)).join(",\n")}\n${indent}]`;
  }
  if (isObject(value)) {
    const keys = Object.keys(value).filter((k) => value[k] !== undefined);
    if (sorted) keys.sort();
    if (keys.length === 0) return "{}";
    const lines = keys.map(
      (k) => `${inner}${JSON.stringify(k)}: ${write(value[k], inner, sorted || k === "parameters")}`,
    );
    return `{\n${lines.join(",\n")}\n${indent}}`;
  }
  return JSON.stringify(value) ?? "null";
}

const ENVELOPE = ["format", "formatVersion", "experiment", "steps"];
const EXPERIMENT: string[] = Object.values(EXPERIMENT_FIELDS);
const STEP: string[] = Object.values(STEP_FIELDS);
const ACTION = Object.values(ACTION_FIELDS).filter((name) => name !== null);

function* check(file: unknown): Work<ImportProblem[]> {
  const problems: ImportProblem[] = [];
  const flag = (path: string, message: string): false => {
    problems.push({ path, message });
    return false;
  };
  const object = (value: unknown, path: string, fields: string[]): value is Record<string, unknown> => {
    if (!isObject(value)) return flag(path, "must be an object ({ … })");
    for (const key of Object.keys(value))
      if (!fields.includes(key)) flag(member(path, key), "is not part of an experiment file");
    return true;
  };
  const list = (value: unknown, path: string, max: number, what: string, within: string): value is unknown[] => {
    if (!Array.isArray(value)) return flag(path, "must be a list ([ … ])");
    if (value.length > max) return flag(path, `has ${value.length} ${what}; ${within} can have at most ${max}`);
    return true;
  };
  const text = (
    owner: Record<string, unknown>,
    key: string,
    path: string,
    max: number,
    need: "required" | "optional",
  ) => {
    const value = owner[key];
    if (value === undefined && need === "optional") return;
    if (typeof value !== "string" || (need === "required" && !value.trim())) {
      flag(member(path, key), need === "required" ? "must be a non-empty string" : "must be a string");
      return;
    }
    if (value.length > max) flag(member(path, key), `must be at most ${max} characters (it has ${value.length})`);
  };
  const values = (value: unknown, path: string, depth: number): void => {
    if (depth > MAX_DEPTH) {
      flag(path, `is nested more than ${MAX_DEPTH} levels deep`);
      return;
    }
    if (typeof value === "string" && value.length > MAX_TEXT)
      flag(path, `must be at most ${MAX_TEXT} characters (it has ${value.length})`);
    if (Array.isArray(value)) value.forEach((v, i) => values(v, `${path}[${i}]`, depth + 1));
    else if (isObject(value)) for (const [k, v] of Object.entries(value)) values(v, member(path, k), depth + 1);
  };

  if (!isObject(file))
    return [{ path: "$", message: "must be an object ({ … }): an experiment file holds one experiment" }];
  if (file.format !== FORMAT)
    return [{ path: "$.format", message: `must be "${FORMAT}": this is not an HRIStudio experiment file` }];
  if (!READABLE_VERSIONS.includes(file.formatVersion as number)) {
    const newer = typeof file.formatVersion === "number" && file.formatVersion > DOCUMENT_VERSION;
    const message = newer
      ? `is ${file.formatVersion}: the file comes from a newer HRIStudio, and this one reads version ${DOCUMENT_VERSION}`
      : `must be ${READABLE_VERSIONS.join(" or ")}`;
    return [{ path: "$.formatVersion", message }];
  }
  const version = file.formatVersion as number;
  const of = (fields: string[], place: FilePlace) => fields.filter((k) => !fieldsAfter(version, place).includes(k));
  const [experimentKeys, stepKeys, actionKeys] = [of(EXPERIMENT, "experiment"), of(STEP, "step"), of(ACTION, "action")];
  object(file, "$", ENVELOPE);
  if (object(file.experiment, "$.experiment", experimentKeys)) {
    text(file.experiment, "name", "$.experiment", MAX_NAME, "required");
    text(file.experiment, "description", "$.experiment", MAX_TEXT, "optional");
    text(file.experiment, "robot", "$.experiment", MAX_NAME, "required");
  }
  if (!list(file.steps, "$.steps", MAX_STEPS, "steps", "an experiment")) return problems;
  const keys = new Map<string, number>();
  file.steps.forEach((step, s) => {
    const path = `$.steps[${s}]`;
    if (!object(step, path, stepKeys)) return;
    text(step, "key", path, MAX_NAME, "required");
    if (typeof step.key === "string" && step.key.trim()) {
      if (keys.has(step.key))
        flag(`${path}.key`, `"${step.key}" is already the key of step ${keys.get(step.key)}; each step needs its own`);
      else keys.set(step.key, s + 1);
    }
    text(step, "name", path, MAX_NAME, "required");
    text(step, "description", path, MAX_TEXT, "optional");
  });
  const leadsTo = (after: unknown, at: string) => {
    if (isObject(after)) {
      if (version < 4) flag(at, `is a loop, which files of version ${version} cannot hold (loops came in version 4)`);
      else loop(after, at);
      return;
    }
    if (after === undefined || after === "end") return;
    if (typeof after !== "string" || !after.startsWith("@"))
      flag(at, 'must be "end" or name a step by "@" and its key, such as "@step-2"');
    else if (!keys.has(after.slice(1))) flag(at, `"${after}" names no step of this file`);
  };
  const loop = (after: Record<string, unknown>, at: string) => {
    if (!object(after, at, ["again", "times", "onward"])) return;
    if (typeof after.again !== "string" || !after.again.startsWith("@"))
      flag(`${at}.again`, 'must name the step it goes back to by "@" and its key, such as "@step-2"');
    else if (!keys.has(after.again.slice(1))) flag(`${at}.again`, `"${after.again}" names no step of this file`);
    const times = after.times;
    if (typeof times !== "number" || !Number.isInteger(times) || times < 1 || times > MAX_LOOP_TIMES)
      flag(`${at}.times`, `must be a whole number of times, from 1 to ${MAX_LOOP_TIMES}`);
    if (isObject(after.onward)) flag(`${at}.onward`, 'must be "end" or name a step: a loop cannot go on into another');
    else leadsTo(after.onward, `${at}.onward`);
  };
  const timeLimit = (owner: Record<string, unknown>, path: string) => {
    const limit = owner.timeLimit;
    const at = `${path}.timeLimit`;
    if (limit === undefined || !object(limit, at, ["seconds", "after"])) return;
    const seconds = limit.seconds;
    if (typeof seconds !== "number" || !(seconds > 0) || seconds > MAX_TIME_LIMIT_SECONDS)
      flag(`${at}.seconds`, `must be a number of seconds, more than 0 and at most ${MAX_TIME_LIMIT_SECONDS}`);
    leadsTo(limit.after, `${at}.after`);
  };
  // Keys are all known only now: a step may lead to one further down.
  file.steps.forEach((step, s) => {
    if (!isObject(step)) return;
    leadsTo(step.after, `$.steps[${s}].after`);
    timeLimit(step, `$.steps[${s}]`);
  });
  /** Variants by condition name, each checked by `each` at its place. */
  const variants = (owner: Record<string, unknown>, path: string, each: (variant: unknown, at: string) => void) => {
    if (owner.variants === undefined || !object(owner.variants, `${path}.variants`, Object.keys(owner.variants ?? {})))
      return;
    const named = Object.entries(owner.variants);
    if (!named.length) flag(`${path}.variants`, "must hold at least one condition's variant, or be left out");
    for (const [condition, variant] of named) {
      const at = member(`${path}.variants`, condition);
      if (!condition.trim() || condition.length > MAX_NAME)
        flag(at, `must be under a condition's name, of 1 to ${MAX_NAME} characters`);
      each(variant, at);
    }
  };
  const parameters = (owner: Record<string, unknown>, path: string) => {
    if (owner.parameters === undefined) return;
    if (!isObject(owner.parameters)) flag(`${path}.parameters`, "must be an object ({ … })");
    else values(owner.parameters, `${path}.parameters`, 0);
  };
  /** Where an action of `type` leads (a wait's events, a branch's targets), each named by a key of this file. */
  const leads = (type: unknown, parameters: unknown, path: string) => {
    if (!isObject(parameters)) return;
    if (type === "wait_for" && Array.isArray(parameters.events))
      parameters.events.forEach((event: unknown, e) => {
        if (isObject(event)) leadsTo(event.after, `${path}.parameters.events[${e}].after`);
      });
    if (type === "branch" && isObject(parameters.targets)) {
      for (const [option, target] of Object.entries(parameters.targets)) {
        const at = member(`${path}.parameters.targets`, option);
        if (typeof target !== "string" || !target.startsWith("@"))
          flag(at, 'must name a step by "@" and its key, such as "@step-2"');
        else if (!keys.has(target.slice(1))) flag(at, `"${target}" names no step of this file`);
      }
    }
  };
  const actionAt = (action: unknown, path: string, fields: string[]) => {
    if (!object(action, path, fields)) return;
    variants(action, path, (variant, at) => {
      if (!object(variant, at, ["type", "parameters"])) return;
      text(variant, "type", at, MAX_NAME, "optional");
      parameters(variant, at);
      leads(variant.type ?? action.type, variant.parameters, at);
    });
    text(action, "type", path, MAX_NAME, "required");
    text(action, "name", path, MAX_NAME, "optional");
    text(action, "note", path, MAX_NOTE, "optional");
    text(action, "runTogether", path, MAX_NAME, "optional");
    timeLimit(action, path);
    if (action.runTogether === "")
      flag(`${path}.runTogether`, "must be a non-empty string, or left out for an action that runs alone");
    parameters(action, path);
    leads(action.type, action.parameters, path);
  };
  for (const [s, step] of file.steps.entries()) {
    yield;
    if (!isObject(step) || !list(step.actions, `$.steps[${s}].actions`, MAX_ACTIONS, "actions", "a step")) continue;
    step.actions.forEach((action, a) => actionAt(action, `$.steps[${s}].actions[${a}]`, actionKeys));
    variants(step, `$.steps[${s}]`, (variant, at) => {
      if (
        !object(variant, at, ["actions"]) ||
        !list(variant.actions, `${at}.actions`, MAX_ACTIONS, "actions", "a step")
      )
        return;
      // A variant's actions have no variants of their own.
      const own = actionKeys.filter((k) => k !== "variants");
      variant.actions.forEach((action, a) => actionAt(action, `${at}.actions[${a}]`, own));
    });
  }
  return problems;
}

function isObject(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function member(path: string, key: string): string {
  return /^[A-Za-z_$][\w$]*$/.test(key) ? `${path}.${key}` : `${path}[${JSON.stringify(key)}]`;
}
