// What to call a robot's event wherever a person reads it (the wizard's wait
// panel, the engine's refusals): the name its plugin gives ("Head touched"),
// or its id when the plugin is gone or never declared it.
import type { Plugin } from "./types";

/** Names of a robot's events, by id. */
export type EventNames = Readonly<Record<string, string>>;

export const NO_EVENT_NAMES: EventNames = {};

export const eventNamesOf = (plugin: Plugin | null): EventNames =>
  Object.fromEntries((plugin?.events ?? []).map((e) => [e.id, e.name]));

export const eventName = (id: string, names: EventNames): string => names[id] ?? id;
