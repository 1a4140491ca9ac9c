// The designer's undo and redo: each command a researcher gives makes a new
// draft, kept with its label so the buttons can say what they undo ("Undo
// move action"); typing, many commands, undoes as one.
import type { DesignDraft, NewId } from "./types";

export interface Command {
  /** What the undo button says: "Undo move action". */
  label: string;
  /** Typing is many commands; consecutive ones with the same key undo as one. */
  mergeKey?: string;
  apply(draft: DesignDraft, newId: NewId): DesignDraft;
}

export interface History {
  present: DesignDraft;
  past: Array<{ label: string; draft: DesignDraft; mergeKey?: string }>;
  future: Array<{ label: string; draft: DesignDraft }>;
}

const HISTORY_LIMIT = 200;

export function startHistory(draft: DesignDraft): History {
  return { present: draft, past: [], future: [] };
}

export function execute(history: History, command: Command, newId: NewId): History {
  const next = command.apply(history.present, newId);
  if (next === history.present) return history;
  const last = history.past.at(-1);
  if (command.mergeKey && last?.mergeKey === command.mergeKey && history.future.length === 0)
    return { ...history, present: next };
  const entry = { label: command.label, draft: history.present, mergeKey: command.mergeKey };
  return { present: next, past: [...history.past, entry].slice(-HISTORY_LIMIT), future: [] };
}

export function undo(history: History): History {
  const last = history.past.at(-1);
  if (!last) return history;
  return {
    present: last.draft,
    past: history.past.slice(0, -1),
    future: [{ label: last.label, draft: history.present }, ...history.future],
  };
}

export function redo(history: History): History {
  const [first, ...rest] = history.future;
  if (!first) return history;
  return {
    present: first.draft,
    past: [...history.past, { label: first.label, draft: history.present }],
    future: rest,
  };
}
