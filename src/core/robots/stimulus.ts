// Making the simulated robot sense something: a person on its Robot page
// touches its head, says a phrase or steps close, and the simulator publishes
// what a real robot's sensor would, on the event's own topic and message
// type. Declared here, below both the simulator and the page; the messages
// are built from the event's condition, so every declared event can be fired.
import type { Condition, FieldValue, RobotEvent } from "../plugins/types";
import { fieldType } from "./messages";

/** Where the page says what to sense (ours, only on the simulator): a Stimulus as JSON in a std_msgs/String. */
export const STIMULUS_TOPIC = "/hristudio/stimulus";
/** Where the simulator lists what it can be made to sense (Sensable[] as JSON), every second. */
export const SENSABLE_TOPIC = "/hristudio/sensable";

/** A touch (pressed, then released), a phrase heard with a confidence, or someone stepping close or away. */
export type Stimulus =
  | { event: string; touch: true }
  | { event: string; heard: string; confidence: number }
  | { event: string; near: boolean };

export interface Sensable {
  id: string;
  name: string;
  kind: Condition["kind"];
}

export const sensable = (events: RobotEvent[]): Sensable[] =>
  events.map((e) => ({ id: e.id, name: e.name, kind: e.when.kind }));

/** How long a simulated touch is held before it is released: long enough to see, short of a deliberate hold. */
export const TOUCH_MS = 300;

/** A message, as the event's fields say, of a touch pressed and of its release. */
export function touchMessages(event: RobotEvent): {
  pressed: Record<string, unknown>;
  released: Record<string, unknown>;
} {
  const when = event.when as Extract<Condition, { kind: "pressed" }>;
  const which = Object.entries(when.where ?? {}).reduce((m, [path, value]) => withField(m, path, value), {});
  return {
    pressed: withField(which, when.field, when.equals),
    released: withField(which, when.field, releasedValue(when.equals)),
  };
}

/** A message of the recogniser hearing `phrase` with `confidence`, a list or one value as the message's fields are. */
export function heardMessage(event: RobotEvent, phrase: string, confidence: number): Record<string, unknown> {
  const when = event.when as Extract<Condition, { kind: "heard" }>;
  const listed = (path: string, value: unknown) =>
    fieldType(event.messageType, path)?.endsWith("[]") ? [value] : value;
  return withField(
    withField({}, when.field, listed(when.field, phrase)),
    when.confidenceField,
    listed(when.confidenceField, confidence),
  );
}

/** A reading of `distance` metres, in the event's distance field (a list gets it as its one reading). */
export function distanceMessage(event: RobotEvent, distance: number): Record<string, unknown> {
  const { field } = event.when;
  return withField({}, field, fieldType(event.messageType, field)?.endsWith("[]") ? [distance] : distance);
}

/** Where a near event's person stands: well inside when close, well clear when away. */
export function distanceOf(event: RobotEvent, near: boolean): number {
  const when = event.when as Extract<Condition, { kind: "near" }>;
  return near ? when.below / 2 : when.clearAbove * 2;
}

/** The other value of a pressed field: what it is when not pressed. */
function releasedValue(pressed: FieldValue): FieldValue {
  if (typeof pressed === "boolean") return !pressed;
  if (typeof pressed === "number") return pressed === 0 ? 1 : 0;
  return "";
}

/** A copy of the message with the field at a dotted path set. */
function withField(message: Record<string, unknown>, path: string, value: unknown): Record<string, unknown> {
  const [head, ...rest] = path.split(".");
  if (!rest.length) return { ...message, [head!]: value };
  const inner = (message[head!] ?? {}) as Record<string, unknown>;
  return { ...message, [head!]: withField(inner, rest.join("."), value) };
}
