// The shape of a loaded plugin file: the HRIStudio plugin format (as in
// tests/fixtures/hristudio-plugins) plus our additive fields. The JSON
// Schema in plugins/plugin.schema.json is the authority; types.test.ts checks
// these types against it, field by field.

export type JsonValue = string | number | boolean | null | JsonValue[] | { [key: string]: JsonValue };
export type JsonObject = { [key: string]: JsonValue };

export type TrustLevel = "official" | "verified" | "community";
export type TransportKind = "rosbridge" | "ssh" | "http" | "simulated";

/** A parameter's JSON Schema: the one declaration forms, validation and types come from. */
export interface ParameterSchema {
  type: "object";
  properties: Record<string, JsonObject & { type: string; default?: JsonValue }>;
  required?: string[];
  additionalProperties?: boolean;
}

export type PayloadMapping =
  | { type: "static"; payload: JsonObject }
  | { type: "transform"; transformFn: string; payload?: JsonObject }
  | { type: "ssh"; sshCommand: string }
  /** HRIStudio's service call: `payload` is the call's arguments. */
  | { type: "service"; payload?: JsonObject };

/**
 * How an action reaches the robot over rosbridge: a topic publish, a service
 * call, or a ROS 2 action goal (HRIStudio's `action`, whose `messageType` is
 * the goal's message; our `actionType` names the action's type when it is not
 * one goal.ts knows from that message). A topic or service name may hold
 * {parameter} parts (topic.ts).
 */
export type Ros2Dispatch =
  | { topic: string; messageType: string; payloadMapping: PayloadMapping }
  | ServiceDispatch
  | { action: string; actionType?: string; messageType: string; payloadMapping: PayloadMapping };

/**
 * A service call, written our way (`serviceType`, `args`) or HRIStudio's
 * (`messageType`, a payloadMapping of type "service"); the schema asks for
 * one of the two types.
 */
export interface ServiceDispatch {
  service: string;
  serviceType?: string;
  messageType?: string;
  args?: JsonObject;
  payloadMapping?: Extract<PayloadMapping, { type: "service" }>;
}

export interface PluginAction {
  id: string;
  name: string;
  description?: string;
  category: string;
  icon?: string;
  /** Milliseconds; HRIStudio's field. */
  timeout?: number;
  retryable?: boolean;
  parameterSchema: ParameterSchema;
  ros2?: Ros2Dispatch;
  /** Our extension: a request to the robot's REST API. */
  http?: HttpDispatch;
  /** Our extension: how the action is known to be done (completion.ts gives the default when absent). */
  completion?: Completion;
}

/** Which message on a done topic is this action's: the field at a dotted path, compared after {{param}} filling. */
export interface DoneMatch {
  field: string;
  equals?: JsonValue;
  startsWith?: string;
}

/** How an action is known to be done, as a plugin declares it. */
export type Completion =
  | ({ kind: "done_topic"; topic: string; messageType: string; match?: DoneMatch } & Expected)
  | { kind: "service_response" }
  | { kind: "http_response" }
  /** A ROS 2 action goal's result: fulfilled by the transport that sends action goals. */
  | { kind: "action_result" }
  /** The last resort: not confirmed by the robot, and marked so. */
  | ({ kind: "estimated_duration" } & Expected);

/**
 * How long the action takes on the robot: `ms`, plus `msPerChar` per character
 * of the parameter `perCharOf` (a say's text). For a done topic it is added
 * to the action's timeout, so a long say is not timed out while it is spoken.
 */
export interface Expected {
  ms?: number;
  msPerChar?: number;
  perCharOf?: string;
}

export interface HttpDispatch {
  method: "GET" | "POST" | "PUT" | "PATCH" | "DELETE";
  /** Absolute, or relative to the transport's base URL. */
  url: string;
  body?: JsonObject;
}

/** Our extension: which plugin action performs an abstract action, and with what parameters. */
export interface AbstractBinding {
  action: string;
  /** A template over the abstract action's parameters, e.g. {"text": "{{text}}"}. */
  parameters?: JsonObject;
  /** Use this binding only when the abstract parameters have these values. */
  when?: Record<string, string | number | boolean>;
}

/**
 * Something the robot senses: the topic it reports on and the condition on
 * each message that makes it this event. Experiments name it by id.
 */
export interface RobotEvent {
  id: string;
  /** In the researcher's words: "Head touched". */
  name: string;
  description?: string;
  topic: string;
  messageType: string;
  /** Least milliseconds between the messages read (rosbridge's throttle): for a topic that reports all along, such as a sonar. */
  throttleRate?: number;
  /** The condition on the message that makes it this event (senses.ts matches it). */
  when: Condition;
}

/** A scalar a message field is compared with. */
export type FieldValue = string | number | boolean;

/**
 * The condition on a topic's messages, one of three kinds; each `field` is a
 * dotted path into the message.
 * - pressed: the field becomes `equals` (a touch sensor pressed), among the
 *   messages whose `where` fields hold those values (which sensor). Once per
 *   press: not again while held, not on release.
 * - heard: one of `words` (any case) recognised with at least
 *   `minConfidence`; `field` lists the words heard and `confidenceField`
 *   their confidences in the same order.
 * - near: the distance in `field` (a number, or a list whose nearest
 *   reading counts) stays under `below` for `forMs`; it happens again only
 *   once the distance has been above `clearAbove`, so a distance flapping
 *   around `below` is one event.
 */
export type Condition =
  | { kind: "pressed"; field: string; equals: FieldValue; where?: Record<string, FieldValue> }
  | { kind: "heard"; field: string; confidenceField: string; words: string[]; minConfidence: number }
  | { kind: "near"; field: string; below: number; forMs: number; clearAbove: number };

/** One event the robot sensed: which, when by the robot's own clock (its message's header stamp, else the runtime's), and the message that matched. */
export interface Sensed {
  event: string;
  /** Milliseconds since the epoch. */
  at: number;
  message: JsonValue;
}

export interface Plugin {
  robotId: string;
  name: string;
  description?: string;
  version: string;
  pluginApiVersion: string;
  trustLevel?: TrustLevel;
  category?: string;
  capabilities?: string[];
  ros2Config?: { namespace?: string; nodePrefix?: string; defaultTopics?: Record<string, string> };
  transport?: TransportKind;
  actions: PluginAction[];
  abstract?: Record<string, AbstractBinding | AbstractBinding[]>;
  unsupported?: Array<{ action: string; reason: string }>;
  /** Our extension: the actions an emergency stop or abort sends, in order (e.g. stop walking, stop speech, stop animation). */
  halt?: string[];
  /** Robot state the runtime logs as trial samples during a trial. */
  stateTopics?: Array<{ topic: string; messageType: string; throttleRate?: number }>;
  /** The robot's own camera (sensor_msgs/CompressedImage): the wizard and observers see it live; never logged. */
  camera?: { topic: string; messageType: string; throttleRate?: number };
  /** Our extension: what the robot senses and reports (a touch, a heard word, something close), which a "Wait for" can wait for. */
  events?: RobotEvent[];
  /** Every other field of the file, kept as written. */
  [extra: string]: unknown;
}

export interface PluginRepository {
  id: string;
  name: string;
  trust?: TrustLevel;
  pluginApiVersion?: string;
  [extra: string]: unknown;
}
