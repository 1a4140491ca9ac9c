// A trial as an MCAP file, the log format Foxglove and Lichtblick open: the
// robot's state samples (a channel per topic), the commands sent to the
// robot and every trial event (as foxglove.Log), each a JSON message with the
// JSON Schema of its topic's messages, on a time axis that starts at the
// trial's t0, so a roboticist sees the robot's state beside what the wizard
// did. Messages are written in time order.
import { type IWritable, McapWriter } from "@mcap/core";
import type { Sample } from "@/core/analysis/exports";
import {
  LOG_SCHEMA,
  logOf,
  nanosecondsAt,
  plottable,
  sampleSchemaName,
  schemaOf,
  type JsonSchema,
} from "@/core/analysis/mcap-messages";
import type { StoredEvent } from "@/core/trial";

/** The channel of every trial event, and of the commands sent to the robot (the dispatched actions, with what was sent). */
export const EVENTS_TOPIC = "/hristudio/events";
export const COMMANDS_TOPIC = "/hristudio/robot_commands";

interface Message {
  at: bigint;
  data: unknown;
}

export async function trialMcap({
  trialId,
  t0,
  events,
  samples,
  rosTypes = new Map(),
}: {
  trialId: string;
  /** The ROS type of each state topic, as the robot's plugin declares it: the topic's schema is named for it. */
  rosTypes?: Map<string, string>;
  /** The trial's t0, or (never started) when it was created: samples and events are placed from it. */
  t0: Date;
  events: StoredEvent[];
  samples: Sample[];
}): Promise<Uint8Array> {
  const start = t0.getTime();
  // Events before the start have no time from t0: they are placed at their server time, and none before the epoch.
  const atOf = (relMs: number) => {
    const at = nanosecondsAt(start, relMs);
    return at < 0n ? 0n : at;
  };
  const eventAt = (e: StoredEvent) => atOf(e.relMs ?? e.serverTime.getTime() - start);
  // Each message as its JSON reads back (dates as text), so its schema is read off what is written.
  const asJson = (data: unknown): unknown => JSON.parse(JSON.stringify(data));
  const topics = new Map<string, { schemaName: string; schema: JsonSchema; messages: Message[] }>();
  topics.set(EVENTS_TOPIC, {
    schemaName: "foxglove.Log",
    schema: LOG_SCHEMA,
    messages: events.map((e) => {
      const at = eventAt(e);
      return { at, data: logOf(e, at) };
    }),
  });
  const commands = events
    .filter((e) => e.type === "action.dispatched")
    .map((e) => ({ at: eventAt(e), data: asJson(e) }));
  if (commands.length)
    topics.set(COMMANDS_TOPIC, {
      schemaName: "hristudio.RobotCommand",
      schema: schemaOf(commands.map((c) => c.data)),
      messages: commands,
    });
  const byTopic = new Map<string, Sample[]>();
  for (const s of samples) (byTopic.get(s.topic) ?? byTopic.set(s.topic, []).get(s.topic)!).push(s);
  for (const [topic, list] of byTopic) {
    const unwrapped = list.map((s) => plottable(s.data));
    // Samples come from jsonb (or JSON text, unwrapped): already as their JSON reads back, with no copy made.
    const messages = list.map((s, i) => ({ at: atOf(s.relMs), data: unwrapped[i] }));
    const schema = schemaOf(messages.map((m) => m.data));
    // A String unwrapped into its JSON fields is no longer of the type the robot declared.
    const declared = unwrapped.every((d, i) => d === list[i]!.data) ? (rosTypes.get(topic) ?? null) : null;
    topics.set(topic, { schemaName: sampleSchemaName(topic, schema, declared), schema, messages });
  }

  const buffer = new Pieces();
  const writer = new McapWriter({ writable: buffer });
  await writer.start({ profile: "", library: "HRIStudio" });
  const encoder = new TextEncoder();
  // One schema record per shape: topics whose messages have the same name and shape share it.
  const schemaIds = new Map<string, number>();
  const ordered: Array<Message & { channelId: number }> = [];
  for (const [topic, { schemaName, schema, messages }] of topics) {
    const data = JSON.stringify(schema);
    const key = `${schemaName}\n${data}`;
    let schemaId = schemaIds.get(key);
    if (schemaId === undefined) {
      schemaId = await writer.registerSchema({ name: schemaName, encoding: "jsonschema", data: encoder.encode(data) });
      schemaIds.set(key, schemaId);
    }
    const channelId = await writer.registerChannel({
      schemaId,
      topic,
      messageEncoding: "json",
      metadata: new Map([["trial_id", trialId]]),
    });
    for (const m of messages) ordered.push({ ...m, channelId });
  }
  ordered.sort((a, b) => (a.at < b.at ? -1 : a.at > b.at ? 1 : 0));
  const sequences = new Map<number, number>();
  for (const m of ordered) {
    const sequence = (sequences.get(m.channelId) ?? 0) + 1;
    sequences.set(m.channelId, sequence);
    await writer.addMessage({
      channelId: m.channelId,
      sequence,
      logTime: m.at,
      publishTime: m.at,
      data: encoder.encode(JSON.stringify(m.data)),
    });
  }
  await writer.end();
  return buffer.whole();
}

/**
 * Where the writer writes: its pieces kept as they come, joined once at the end. (@mcap/core's TempBuffer
 * copies all it holds on every write, gigabytes over a long trial's 50 MB.)
 */
class Pieces implements IWritable {
  #pieces: Uint8Array[] = [];
  #size = 0;
  position() {
    return BigInt(this.#size);
  }
  async write(data: Uint8Array) {
    // A copy: the writer may fill its buffer again once this returns.
    this.#pieces.push(data.slice());
    this.#size += data.byteLength;
  }
  whole(): Uint8Array {
    const out = new Uint8Array(this.#size);
    let at = 0;
    for (const piece of this.#pieces) {
      out.set(piece, at);
      at += piece.byteLength;
    }
    return out;
  }
}
