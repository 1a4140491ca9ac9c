// The designer's library: the engine's control blocks, the abstract actions
// every robot may map, and the chosen robot's own actions. Each block carries
// the JSON Schema its properties form is generated from.
import {
  ABSTRACT_ACTIONS,
  parseActionType,
  robotActionType,
  withDefaults,
  type ParameterSchema,
  type Plugin,
} from "../plugins";

export type BlockCategory = "speech" | "movement" | "timing" | "wizard" | "logic" | "robot";

export interface Block {
  type: string;
  name: string;
  category: BlockCategory;
  description: string;
  parameterSchema: ParameterSchema;
}

const none: ParameterSchema = { type: "object", properties: {}, additionalProperties: false };

/** Blocks the trial engine carries out itself; every robot has them. */
export const CONTROL_BLOCKS: Block[] = [
  {
    type: "wizard_instruction",
    name: "Wizard instruction",
    category: "wizard",
    description: "A note shown only to the wizard, e.g. “Hand the participant the card.”",
    parameterSchema: {
      type: "object",
      properties: { text: { type: "string", title: "Instruction", minLength: 1, maxLength: 2000 } },
      required: ["text"],
      additionalProperties: false,
    },
  },
  {
    type: "record_answer",
    name: "Record answer",
    category: "logic",
    description: "The wizard picks the participant's answer from named options.",
    parameterSchema: {
      type: "object",
      properties: {
        prompt: { type: "string", title: "Question for the wizard", maxLength: 500 },
        options: {
          type: "array",
          title: "Answers",
          minItems: 2,
          maxItems: 12,
          items: {
            type: "object",
            properties: {
              id: { type: "string", minLength: 1, maxLength: 100 },
              label: { type: "string", title: "Answer", minLength: 1, maxLength: 200 },
            },
            required: ["id", "label"],
            additionalProperties: false,
          },
        },
      },
      required: ["options"],
      additionalProperties: false,
    },
  },
  {
    type: "branch",
    name: "Branch",
    category: "logic",
    description: "Right after “Record answer”: for each answer, the step the trial goes to.",
    parameterSchema: {
      type: "object",
      properties: { targets: { type: "object", title: "Go to", additionalProperties: { type: "string" } } },
      required: ["targets"],
      additionalProperties: false,
    },
  },
  {
    type: "wait_for",
    name: "Wait for",
    category: "logic",
    description:
      "Waits for something the robot senses (a touch, a word it hears): each event leads to its step; the wizard can always go on.",
    parameterSchema: {
      type: "object",
      properties: {
        events: {
          type: "array",
          title: "Events",
          maxItems: 12,
          items: {
            type: "object",
            properties: {
              id: { type: "string", minLength: 1, maxLength: 100 },
              event: { type: "string", title: "Event", minLength: 1, maxLength: 100 },
              after: {
                type: "object",
                title: "Leads to",
                properties: {
                  to: { type: "string", enum: ["next", "step", "end"] },
                  stepId: { type: "string", maxLength: 100 },
                },
                required: ["to"],
                additionalProperties: false,
              },
            },
            required: ["id", "event", "after"],
            additionalProperties: false,
          },
        },
      },
      required: ["events"],
      additionalProperties: false,
    },
  },
  {
    type: "end_trial",
    name: "End trial",
    category: "logic",
    description: "Ends the trial here.",
    parameterSchema: none,
  },
];

const CATEGORY: Record<string, BlockCategory> = { say: "speech", play_audio: "speech", pause: "timing" };

/** The abstract actions, named the way the library shows them. */
export const ABSTRACT_BLOCKS: Block[] = ABSTRACT_ACTIONS.map((a) => ({
  type: a.id,
  name: a.name,
  category: CATEGORY[a.id] ?? "movement",
  description: a.runtime
    ? "Carried out by the platform on any robot."
    : a.browserFallback
      ? "One of the study's sounds, played by the robot where it can, otherwise by the wizard's browser."
      : "Runs on any robot whose plugin maps it.",
  parameterSchema: a.parameterSchema,
}));

function robotBlocks(plugin: Plugin): Block[] {
  return plugin.actions.map((a) => ({
    type: robotActionType(plugin.robotId, a.id),
    name: a.name,
    category: "robot",
    description: a.description ?? `${plugin.name}: ${a.category}`,
    parameterSchema: a.parameterSchema,
  }));
}

/**
 * Actions that wait for the wizard's choice start on their own: the wizard's controls put one
 * question at a time, as the first of what starts next, so one of these never runs together.
 */
export const WAITS_FOR_CHOICE: ReadonlySet<string> = new Set(["record_answer", "branch", "wait_for"]);

/**
 * Blocks whose settings are more than a form (a question's answers, a wait's events, a branch's targets, a
 * sound): set on the shared action only; a condition's variant or own copy changes no more than their text.
 */
export const OWN_EDITORS: ReadonlySet<string> = new Set([...WAITS_FOR_CHOICE, "play_audio"]);

/**
 * Not an action: a tool that makes an action start together with the one
 * above it (dropped onto it, or with the action selected). The group is then
 * a frame around the actions, each still editable on its own.
 */
export const RUN_TOGETHER: Block = {
  type: "run_together",
  name: "Run together",
  category: "timing",
  description: "Drop onto an action to start it together with the action above it (say, a gesture with its speech).",
  parameterSchema: none,
};

/** Everything the library offers for an experiment on this robot. */
export function library(plugin: Plugin | null): Block[] {
  return [...CONTROL_BLOCKS, RUN_TOGETHER, ...ABSTRACT_BLOCKS, ...(plugin ? robotBlocks(plugin) : [])];
}

/** The block behind an action's type, if the library knows it. */
export function blockFor(type: string, plugin: Plugin | null): Block | undefined {
  const parsed = parseActionType(type);
  if (parsed.kind === "robot")
    return plugin && parsed.robotId === plugin.robotId ? robotBlocks(plugin).find((b) => b.type === type) : undefined;
  return CONTROL_BLOCKS.find((b) => b.type === type) ?? ABSTRACT_BLOCKS.find((b) => b.type === type);
}

/** What a freshly dropped block starts with: its schema's defaults. */
export function initialParameters(block: Block, newId: () => string): Record<string, unknown> {
  if (block.type === "record_answer") {
    return {
      prompt: "",
      options: [
        { id: newId(), label: "Yes" },
        { id: newId(), label: "No" },
      ],
    };
  }
  if (block.type === "branch") return { targets: {} };
  if (block.type === "wait_for") return { events: [] };
  return withDefaults(block.parameterSchema, {});
}
