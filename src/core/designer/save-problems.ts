// A save the server refused, said about the step and action it concerns:
// 'Step 2 "Quiz", action 1 "Say": Label must be at most 200 characters.'
// rather than the input's path ("steps.1.actions.0.name: must be at most…").
import { parseActionType } from "../plugins";
import { blockFor } from "./blocks";
import type { DesignDraft } from "./types";

export interface FieldIssue {
  field: string;
  message: string;
}

// What the properties form calls each field the save sends.
const LABELS: Record<string, string> = {
  name: "Name",
  description: "Description",
  robotId: "Robot",
  after: "Then",
  type: "Kind of action",
  parameters: "Settings",
  parallelGroup: "Run together",
  // Said of the list's owner: "The step can have at most 500 actions."
  actions: "The step",
  steps: "The experiment",
};

const ACTION_LABELS: Record<string, string> = { name: "Label" };
const STEP_LABELS: Record<string, string> = { name: "Step name" };

export function describeSaveIssues(draft: DesignDraft, issues: FieldIssue[]): string {
  return issues.map((issue) => sentence(draft, issue)).join(" ");
}

function sentence(draft: DesignDraft, { field, message }: FieldIssue): string {
  const path = field.split(".");
  const where: string[] = [];
  let labels = LABELS;
  let key = path.at(-1) ?? "";
  if (path[0] === "steps" && path.length > 2) {
    const s = Number(path[1]);
    const step = draft.steps[s];
    where.push(`Step ${s + 1}${step?.name.trim() ? ` "${step.name.trim()}"` : ""}`);
    labels = { ...LABELS, ...STEP_LABELS };
    if (path[2] === "actions" && path.length > 4) {
      const a = Number(path[3]);
      const action = step?.actions[a];
      where.push(`action ${a + 1}${action ? ` "${actionName(action.name, action.type)}"` : ""}`);
      labels = { ...LABELS, ...ACTION_LABELS };
    }
    key = path[2] === "actions" && path.length > 4 ? path[4]! : path[2]!;
  } else if (path[0] === "details") {
    key = path[1] ?? "";
  }
  const things = key === "steps" ? "steps" : key === "actions" ? "actions" : "characters";
  const plain = plainZod(message, things);
  // Our own messages start with the field's name ("Step name must not be empty").
  const said = /^[A-Z]/.test(plain) ? plain : `${labels[key] ?? key} ${plain}`;
  return `${where.length ? `${where.join(", ")}: ` : ""}${said}.`;
}

/** Zod's defaults, for limits no message was written for. */
function plainZod(message: string, things: string): string {
  const big = /^Too big: expected \w+ to have <=?(\d+)/.exec(message);
  if (big) return `can have at most ${big[1]} ${things}`;
  const small = /^Too small: expected \w+ to have >=?(\d+)/.exec(message);
  if (small) return small[1] === "1" ? "must not be empty" : `needs at least ${small[1]} ${things}`;
  if (/^Invalid\b/.test(message)) return "is not valid";
  return message;
}

function actionName(name: string, type: string): string {
  if (name.trim()) return name.trim();
  const parsed = parseActionType(type);
  return blockFor(type, null)?.name ?? (parsed.kind === "robot" ? parsed.actionId : type);
}
