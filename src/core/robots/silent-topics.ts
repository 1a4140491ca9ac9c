// Which of a robot's declared topics are silent, and why, in the words a
// wizard reads. A bridge that refuses a subscription mostly says so only in
// its own log (transcript 06: a ROS 1 rosbridge refuses every ROS 2 type name
// `pkg/msg/Type` without a frame), so silence itself is the evidence; a
// bridge that does send a `status` frame names the refused subscription by
// its id, and its words are given too.

/**
 * The plugin format declares no rate for a state topic: one is expected about
 * this often, or as often as its throttleRate lets through when it has one.
 */
export const EXPECTED_EVERY_MS = 1000;
/** Silent after this many expected messages missed, and never before SILENT_FLOOR_MS: one late message is no fault. */
const MISSED = 5;
export const SILENT_FLOOR_MS = 5000;

export interface WatchedTopic {
  topic: string;
  messageType: string;
  /**
   * state: the robot sends it steadily; completion: it answers actions (a done topic); event: it speaks when
   * the robot senses something (a touch, a word), so its silence says nothing, only a bridge's refusal does.
   */
  kind: "state" | "completion" | "event";
  throttleRate?: number;
  /** When it was subscribed on the live connection. */
  since: number;
  /** When its last message came; null if none yet. */
  lastAt: number | null;
  /** The bridge's words refusing the subscription, if it said any. */
  refused: string | null;
  /** An action waited for it until the action's timeout (a completion topic). */
  waitedOut: boolean;
}

/** What a bridge's status frame refused: roslib's ids name the op and the topic ("subscribe:/joint_states:7"). */
export interface Refusal {
  op: "subscribe" | "advertise";
  topic: string;
  text: string;
}

export function refusalOf(frame: unknown): Refusal | null {
  const f = frame as { op?: unknown; level?: unknown; id?: unknown; msg?: unknown } | null;
  if (f?.op !== "status" || f.level !== "error" || typeof f.id !== "string") return null;
  const named = /^(subscribe|advertise):(\/[^:]*):/.exec(f.id);
  if (!named) return null;
  const said = typeof f.msg === "string" ? f.msg : "";
  // rosbridge prefixes its words with the op ("subscribe: … is not a valid type string").
  const text =
    said
      .replace(/^(subscribe|advertise):\s*/, "")
      .trim()
      .replace(/\.+$/, "") || "(no text)";
  return { op: named[1] as Refusal["op"], topic: named[2]!, text };
}

export const expectedEveryMs = (t: Pick<WatchedTopic, "throttleRate">) =>
  t.throttleRate && t.throttleRate > 0 ? t.throttleRate : EXPECTED_EVERY_MS;

export const silentAfterMs = (t: Pick<WatchedTopic, "throttleRate">, floorMs = SILENT_FLOOR_MS) =>
  Math.max(floorMs, MISSED * expectedEveryMs(t));

const seconds = (ms: number) => `${Number((ms / 1000).toPrecision(3))} s`;

/** ROS 2's `pkg/msg/Type` as a ROS 1 bridge names it (`pkg/Type`); null if the name is not ROS 2's spelling. */
function ros1Name(messageType: string): string | null {
  const m = /^([^/]+)\/(?:msg|srv|action)\/([^/]+)$/.exec(messageType);
  return m ? `${m[1]}/${m[2]}` : null;
}

/** The usual reason a topic never spoke at all. */
function usualCause(t: WatchedTopic): string {
  const ros1 = ros1Name(t.messageType);
  if (ros1)
    return `the usual causes are a ROS 1 bridge, which refuses the ROS 2 type name ${t.messageType} without telling us (it names it ${ros1}), or nothing on the robot publishing ${t.topic}`;
  return `the usual cause is that nothing on the robot publishes ${t.topic}, or publishes it as another type than ${t.messageType}`;
}

function expected(t: WatchedTopic): string {
  if (t.kind === "event") return "expected when the robot senses something";
  return t.kind === "state"
    ? `expected about every ${seconds(expectedEveryMs(t))}`
    : "expected after each action that waits for it";
}

/** Why the topic is silent, in plain words; null while it is not. The same words while nothing changes. */
export function silence(t: WatchedTopic, now: number, floorMs = SILENT_FLOOR_MS): string | null {
  if (t.refused !== null) {
    const ros1 = ros1Name(t.messageType);
    const why =
      ros1 && /not a valid type/i.test(t.refused)
        ? `the bridge refused its type ${t.messageType} — a ROS 1 bridge names it ${ros1}`
        : `the bridge refused to subscribe to it as ${t.messageType}: ${t.refused}`;
    return `The robot never sent ${t.topic} (${expected(t)}): ${why}.`;
  }
  if (t.kind === "event") return null;
  if (t.kind === "completion") {
    if (!t.waitedOut || t.lastAt !== null) return null;
    return `The robot never sent ${t.topic} (${expected(t)}; an action waited for it until its timeout): ${usualCause(t)}.`;
  }
  const after = silentAfterMs(t, floorMs);
  if (now - (t.lastAt ?? t.since) < after) return null;
  if (t.lastAt === null)
    return `The robot never sent ${t.topic} (${expected(t)}; nothing in ${seconds(after)}): ${usualCause(t)}.`;
  return `The robot stopped sending ${t.topic} (${expected(t)}; nothing for ${seconds(after)}): the node that publishes it on the robot may have stopped.`;
}

/** An action's topic the bridge would not carry (a refused advertise). */
export function refusedAdvertise(topic: string, messageType: string | null, text: string): string {
  const ros1 = messageType ? ros1Name(messageType) : null;
  if (ros1 && /not a valid type/i.test(text))
    return `The robot's bridge refused to carry ${topic}: it refused the type ${messageType} — a ROS 1 bridge names it ${ros1}.`;
  return `The robot's bridge refused to carry ${topic}${messageType ? ` as ${messageType}` : ""}: ${text}.`;
}
