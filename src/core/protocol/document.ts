// The experiment document, declared once. The designer's draft, the published
// snapshot, the design procedure's input, the exchange file and the trial
// engine's protocol are all this shape or a part of it; their types are
// derived here (or from here), never written again. Messages are in the
// researcher's words: they reach the designer as they are.
//
// The document carries its format version (a snapshot's schemaVersion, a
// file's formatVersion); ./versions.ts reads every earlier one. What the
// issue's later parts add goes here, each a bump of DOCUMENT_VERSION with its
// upgrade in ./versions.ts (time limits came in 3, bounded loops in 4,
// variants per condition in 5).
import { z } from "zod";

/**
 * How large a design may be: steps in an experiment, actions in a step, and
 * actions in all. The last keeps the largest design (about 2 MB as a file)
 * imported, saved and published in seconds; 500 steps of 500 actions would not be.
 * Then the characters of a name, a description and a note for the wizard.
 */
export const DESIGN_LIMITS = {
  steps: 500,
  actionsPerStep: 500,
  actions: 50_000,
  name: 200,
  description: 5000,
  note: 2000,
} as const;
const description = z
  .string()
  .max(DESIGN_LIMITS.description, `must be at most ${DESIGN_LIMITS.description} characters`)
  .default("");
const plain = (label: string, max: number) =>
  z
    .string({ error: `${label} must be text` })
    .trim()
    .max(max, `${label} must be at most ${max} characters`);
const named = (label: string, max: number) => plain(label, max).min(1, `${label} must not be empty`);
const key = z.string({ error: "is required" }).min(1, "is required").max(100, "is not a valid id");

/**
 * Where a step leads once its actions are done and no branch took the trial
 * elsewhere: the next step in the list (the last step's "next" ends the
 * trial), a named step (answers rejoin this way), or the trial's end.
 */
const onwardSchema = z.discriminatedUnion(
  "to",
  [
    z.object({ to: z.literal("next") }),
    z.object({ to: z.literal("step"), stepId: key }),
    z.object({ to: z.literal("end") }),
  ],
  { error: 'must say where the step leads: "next", a step, or "end"' },
);

/** The most times a loop may go round: more is not a re-ask but a trial that never ends for the participant. */
export const MAX_LOOP_TIMES = 20;

/**
 * "Go back to <step>, at most K times, then …": the way back is taken while
 * it has been taken fewer than K times in this trial, then "onward" (never
 * another loop, so a bound always ends).
 */
export const loopSchema = z.object({
  to: z.literal("again"),
  stepId: key,
  times: z
    .number({ error: "must be a number of times" })
    .int("must be a whole number of times")
    .min(1, "must be at least 1 time")
    .max(MAX_LOOP_TIMES, `must be at most ${MAX_LOOP_TIMES} times`),
  onward: onwardSchema,
});

export const afterSchema = z.discriminatedUnion("to", [onwardSchema, loopSchema], {
  error: 'must say where the step leads: "next", a step, "end", or back to a step ("again")',
});

const MAX_PARAMETERS_BYTES = 64 * 1024;

/** The longest time limit: an hour, longer than any step a participant sits through. */
export const MAX_TIME_LIMIT_SECONDS = 3600;

/**
 * "No answer (or the step not done) in N s → where": a timer the runtime
 * starts, logs and fires. A timer that fires is the protocol, not a deviation.
 */
export const timeLimitSchema = z.object({
  seconds: z
    .number({ error: "must be a number of seconds" })
    .positive("must be more than 0 seconds")
    .max(MAX_TIME_LIMIT_SECONDS, `must be at most ${MAX_TIME_LIMIT_SECONDS} seconds`),
  after: afterSchema,
});

const actionFields = z.object({
  id: key,
  type: named("Action type", DESIGN_LIMITS.name),
  name: plain("Action name", DESIGN_LIMITS.name).default(""),
  parameters: z
    .record(z.string(), z.unknown(), { error: "must be an object of named values" })
    .refine(
      (p) => JSON.stringify(p).length <= MAX_PARAMETERS_BYTES,
      `must be smaller than ${MAX_PARAMETERS_BYTES / 1024} KB`,
    )
    .default({}),
  // Actions that share a group and sit next to each other start together.
  parallelGroup: z.string().trim().min(1).max(100).nullable().default(null),
  /**
   * Guidance for the wizard, shown beside the action during a trial. Left
   * out when empty, so a design without notes hashes as it always did.
   */
  note: plain("Note for the wizard", DESIGN_LIMITS.note).optional(),
  /** A record_answer's "no answer in N s": its clock runs once the actions before it are done. Left out when none. */
  timeLimit: timeLimitSchema.optional(),
});

/**
 * Variants are keyed by the condition's name, not its row id: a name is unique
 * in its study and is what the researcher reads, so an exchange file carried to
 * another study (whose rows have other ids) and a published version read years
 * later still say which condition each variant is for.
 */
const byCondition = <T extends z.ZodType>(variant: T) =>
  z
    .record(named("Condition name", DESIGN_LIMITS.name), variant, { error: "must name each variant's condition" })
    .refine((variants) => Object.keys(variants).length > 0, "must hold at least one condition's variant")
    .optional();

/** What an action does in one condition: its parameters, and its type when the condition runs another action. */
export const actionVariantSchema = z.object({
  type: named("Action type", DESIGN_LIMITS.name).optional(),
  parameters: actionFields.shape.parameters,
});

export const actionSchema = actionFields.extend({
  /** The action in a named condition; a condition without one runs the action as above. Left out when none. */
  variants: byCondition(actionVariantSchema),
});

const stepActions = <T extends z.ZodType>(action: T) =>
  z.array(action).max(DESIGN_LIMITS.actionsPerStep, `A step can hold at most ${DESIGN_LIMITS.actionsPerStep} actions`);

/** A step's actions in one condition, in place of its own (which carry no variants of their own there). */
export const stepVariantSchema = z.object({ actions: stepActions(actionFields) });

export const stepSchema = z.object({
  id: key,
  name: named("Step name", DESIGN_LIMITS.name),
  description,
  /** Absent in documents written before steps said where they lead: the next step. */
  after: afterSchema.optional(),
  /** How long the step may last from its entry before the trial moves on. Left out when none. */
  timeLimit: timeLimitSchema.optional(),
  actions: stepActions(actionSchema),
  /** The step's actions in a named condition; a condition without one runs the step's own. Left out when none. */
  variants: byCondition(stepVariantSchema),
});

export const experimentFields = z.object({
  name: named("Name", DESIGN_LIMITS.name),
  description,
  /** The robot the experiment is designed for: its plugin's robotId. */
  robotId: named("Robot", DESIGN_LIMITS.name),
});

/** "The design has 60,000 actions; the limit is 50,000.", or null: counted before anything else is read of the steps. */
export function actionCountProblem(steps: ReadonlyArray<unknown>): string | null {
  let count = 0;
  for (const step of steps) {
    const actions = (step as { actions?: unknown } | null)?.actions;
    if (Array.isArray(actions)) count += actions.length;
  }
  if (count <= DESIGN_LIMITS.actions) return null;
  const n = (value: number) => value.toLocaleString("en-US");
  return `The design has ${n(count)} actions; the limit is ${n(DESIGN_LIMITS.actions)}.`;
}

/**
 * A design's steps, their number and their actions counted first: a design
 * over a limit is refused with the limit named, before any step is checked.
 */
export function countedSteps<T extends z.ZodType>(steps: T): T {
  const counted = z
    .unknown()
    .superRefine((value, ctx) => {
      if (!Array.isArray(value)) return;
      const problem =
        value.length > DESIGN_LIMITS.steps
          ? `An experiment can hold at most ${DESIGN_LIMITS.steps} steps`
          : actionCountProblem(value);
      if (problem) ctx.addIssue({ code: "custom", message: problem });
    })
    .pipe(steps);
  // Typed as the steps it passes on: callers (the designer's API client too) still see what a step is.
  return counted as unknown as T;
}

export const draftSchema = experimentFields.extend({
  steps: countedSteps(z.array(stepSchema)),
});

export type After = z.infer<typeof afterSchema>;
export type Onward = z.infer<typeof onwardSchema>;
export type Loop = z.infer<typeof loopSchema>;
export type TimeLimit = z.infer<typeof timeLimitSchema>;
export type DesignAction = z.infer<typeof actionSchema>;
export type ActionVariant = z.infer<typeof actionVariantSchema>;
export type StepVariant = z.infer<typeof stepVariantSchema>;
export type DesignStep = z.infer<typeof stepSchema>;
/** What a researcher edits before publishing. Branch targets are step ids (parameters.targets[optionId]). */
export type DesignDraft = z.infer<typeof draftSchema>;

/**
 * The document's format version. 1: steps go on to the next, the snapshot
 * names the robot robotPluginId. 2: a step says where it leads ("after"), the
 * robot is robotId (a note for the wizard came in 2 too, optional, so a
 * design without notes hashes as before). 3: a step and a record_answer may
 * have a time limit ("timeLimit", left out when none, so earlier documents
 * read and hash as they were). 4: an "after" may go back to a step a bounded
 * number of times (`{ to: "again", stepId, times, onward }`). 5: an action
 * and a step may vary by condition ("variants", by condition name, left out
 * when none, likewise).
 */
export const DOCUMENT_VERSION = 5;

/** The published form: the draft under the experiment's id and the document's version, frozen. */
export const snapshotSchema = z.object({
  schemaVersion: z.literal(DOCUMENT_VERSION),
  experiment: experimentFields.extend({ id: key }),
  steps: z.array(stepSchema),
});

export type ProtocolSnapshot = z.infer<typeof snapshotSchema>;

/**
 * What the trial engine needs of a protocol (a published snapshot or a
 * rehearsal's draft): the same steps and actions, of which only ids, types
 * and parameters are required (the wizard's page also shows descriptions and notes).
 */
export interface TrialProtocol {
  steps: Array<
    Pick<DesignStep, "id" | "name" | "after" | "timeLimit"> &
      Partial<Pick<DesignStep, "description">> & {
        actions: Array<
          Pick<DesignAction, "id" | "type" | "parameters"> &
            Partial<Pick<DesignAction, "name" | "parallelGroup" | "note" | "timeLimit">> & {
              /** The condition whose variant this is (./variants.ts); absent when the action is the shared one. */
              variant?: string;
            }
        >;
      }
  >;
}
