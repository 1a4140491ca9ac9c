// What the robot senses: one event's condition matched against each message
// on its topic, in order. Pure: (state, message, time) → (state, sensed or
// null); the caller keeps the state between messages and gives each message
// its time (messageTime: the robot's stamp, else its own clock).
import { fieldAt, robotTimeOf } from "./completion";
import type { Condition, FieldValue, RobotEvent, Sensed } from "./types";

/** What one event remembers between messages: whether its sensor is held, and since when something is near. */
export interface SenseState {
  pressed: boolean;
  nearSince: number | null;
  /** Reported near, not yet clear again. */
  reported: boolean;
}

export const UNSENSED: SenseState = { pressed: false, nearSince: null, reported: false };

export interface SenseStep {
  state: SenseState;
  sensed: Sensed | null;
}

/** Matches one message (taken at `at`, ms since the epoch) against the event's condition. */
export function sense(event: RobotEvent, state: SenseState, message: unknown, at: number): SenseStep {
  const step = stepOf(event.when, state, message, at);
  return {
    state: step.state,
    sensed: step.fired ? { event: event.id, at, message: message as Sensed["message"] } : null,
  };
}

/** The message's time: its header stamp (the robot's clock) when it has one, else `now`. */
export function messageTime(message: unknown, now: number): number {
  const stamped = robotTimeOf(message);
  return stamped === undefined ? now : Date.parse(stamped);
}

function stepOf(
  when: Condition,
  state: SenseState,
  message: unknown,
  at: number,
): { state: SenseState; fired: boolean } {
  switch (when.kind) {
    case "pressed": {
      // Another sensor's message on the same topic says nothing about this one.
      if (Object.entries(when.where ?? {}).some(([field, value]) => fieldAt(message, field) !== value))
        return { state, fired: false };
      const pressed = fieldAt(message, when.field) === when.equals;
      return { state: { ...state, pressed }, fired: pressed && !state.pressed };
    }
    case "heard":
      return { state, fired: heard(when, message) };
    case "near": {
      const distance = nearest(fieldAt(message, when.field));
      // Between below and clearAbove nothing changes: the band that keeps a flapping reading one event.
      if (distance === null || distance > when.clearAbove) return { state: UNSENSED, fired: false };
      if (distance >= when.below) return { state, fired: false };
      const nearSince = state.nearSince ?? at;
      const fired = !state.reported && at - nearSince >= when.forMs;
      return { state: { ...state, nearSince, reported: state.reported || fired }, fired };
    }
  }
}

function heard(when: Extract<Condition, { kind: "heard" }>, message: unknown): boolean {
  const words = listOf(fieldAt(message, when.field));
  const confidences = listOf(fieldAt(message, when.confidenceField));
  const wanted = new Set(when.words.map(normal));
  return words.some(
    (word, i) =>
      typeof word === "string" &&
      wanted.has(normal(word)) &&
      typeof confidences[i] === "number" &&
      confidences[i] >= when.minConfidence,
  );
}

const normal = (word: string) => word.trim().toLowerCase();
const listOf = (value: unknown): unknown[] => (Array.isArray(value) ? value : [value]);

/**
 * The nearest reading: a number, or the least of a list (a laser scan). A
 * reading that is not a positive finite number (rosbridge's null for
 * infinity, a laser's 0 for no return) is nothing near.
 */
function nearest(value: unknown): number | null {
  const readings = listOf(value).filter((v): v is number => typeof v === "number" && Number.isFinite(v) && v > 0);
  return readings.length ? Math.min(...readings) : null;
}

const value = (v: FieldValue) => (typeof v === "string" ? `“${v}”` : String(v));

/** A condition in a paper's words: "its field state became 1 (where button is 1)". */
export function conditionWords(condition: Condition): string {
  switch (condition.kind) {
    case "pressed": {
      const where = Object.entries(condition.where ?? {}).map(([field, v]) => `${field} is ${value(v)}`);
      return `its field ${condition.field} became ${value(condition.equals)}${where.length ? ` where ${where.join(" and ")}` : ""}, once per press`;
    }
    case "heard":
      return `one of the words ${condition.words.map((w) => `“${w}”`).join(", ")} heard with a confidence of at least ${condition.minConfidence}`;
    case "near":
      return `its field ${condition.field} under ${condition.below} for ${condition.forMs} ms, again only after it had been above ${condition.clearAbove}`;
  }
}
