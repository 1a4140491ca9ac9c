// What to call an action wherever a person reads it (the wizard's page, the
// analysis, the exports, ELAN): its label when the researcher gave one,
// otherwise its block's name and its main setting ("Say: Hi! I am Nao…",
// "Pause 3 s", "Posture: Sit"), so an unlabelled action is never nameless.
import type { Plugin } from "../plugins";
import { ABSTRACT_BLOCKS, CONTROL_BLOCKS, library } from "./blocks";

/** Human names of action types, by type: the library's blocks. */
export type ActionNames = Readonly<Record<string, string>>;

const BUILT_IN: ActionNames = Object.fromEntries([...CONTROL_BLOCKS, ...ABSTRACT_BLOCKS].map((b) => [b.type, b.name]));

/** The names the library shows for an experiment on this robot (the built-in blocks when there is no plugin). */
export function actionNamesOf(plugin: Plugin | null): ActionNames {
  return plugin ? Object.fromEntries(library(plugin).map((b) => [b.type, b.name])) : BUILT_IN;
}

/** The setting that says what an action does, in the order looked for: free text first, then choices. */
const MAIN_PARAMETERS = ["text", "prompt", "seconds", "posture", "name", "direction"] as const;
/** The parameters that hold what an action says or asks in words: its main text. */
export const FREE_TEXT_PARAMETERS: readonly string[] = ["text", "prompt"];
const FREE_TEXT = new Set(FREE_TEXT_PARAMETERS);
const SHORT = 32;

/** A setting or a robot's own identifier as words: "animations/Stand/Gestures/Hey_1" → "Hey 1", "turn_left" → "Turn left". */
export function readableValue(value: string): string {
  const words = (value.split("/").filter(Boolean).at(-1) ?? value).replaceAll("_", " ").trim();
  return words.charAt(0).toUpperCase() + words.slice(1);
}

/** Free text cut at a word near SHORT characters, with an ellipsis when cut. */
function shorten(text: string): string {
  const flat = text.replace(/\s+/g, " ").trim();
  if (flat.length <= SHORT) return flat;
  const space = flat.lastIndexOf(" ", SHORT);
  const cut = flat.slice(0, space > SHORT / 2 ? space : SHORT);
  return `${cut.replace(/[\s,;:.–-]+$/, "")}…`;
}

/** The block's name of a type; a type no catalogue names in words ("nao6-ros2.play_animation_bow" → "Play animation bow"). */
export function blockName(type: string, names: ActionNames = BUILT_IN): string {
  return names[type] ?? BUILT_IN[type] ?? (readableValue(type.slice(type.indexOf(".") + 1)) || type);
}

export function actionName(
  action: { type: string; name?: string | null; parameters?: Record<string, unknown> | null },
  names: ActionNames = BUILT_IN,
): string {
  const label = action.name?.trim();
  if (label) return label;
  const block = blockName(action.type, names);
  const parameters = action.parameters ?? {};
  // A sound is named by its file, exactly as the researcher named the file.
  if (action.type === "play_audio" && typeof parameters.name === "string" && parameters.name.trim())
    return `${block}: ${parameters.name.trim()}`;
  const key = MAIN_PARAMETERS.find((k) => {
    const v = parameters[k];
    return (typeof v === "string" && v.trim() !== "") || (typeof v === "number" && Number.isFinite(v));
  });
  if (!key) return block;
  const value = parameters[key] as string | number;
  if (key === "seconds") return `${block} ${value} s`;
  const shown = FREE_TEXT.has(key) ? shorten(String(value)) : readableValue(String(value));
  return shown ? `${block}: ${shown}` : block;
}
