// A trial as an MCAP file, the log format Foxglove and Lichtblick open: the
// robot's state samples (a channel per topic), the commands sent to the
// robot and every trial event, each a JSON message on a time axis that
// starts at the trial's t0, so a roboticist sees the robot's state beside
// what the wizard did. Messages are written in time order.
import { McapWriter, TempBuffer } from "@mcap/core";
import type { Sample } from "@/core/analysis/exports";
import type { StoredEvent } from "@/core/trial";

/** The channel of every trial event, and of the commands sent to the robot (the dispatched actions, with what was sent). */
export const EVENTS_TOPIC = "/hristudio/events";
export const COMMANDS_TOPIC = "/hristudio/robot_commands";

// Foxglove reads JSON messages with a JSON Schema; the messages' shapes vary by topic and robot, so any object.
const ANY_OBJECT = new TextEncoder().encode(JSON.stringify({ type: "object" }));

const nanoseconds = (ms: number) => BigInt(Math.round(ms * 1_000_000));

export async function trialMcap({
  trialId,
  t0,
  events,
  samples,
}: {
  trialId: string;
  /** The trial's t0, or (never started) when it was created: samples and events are placed from it. */
  t0: Date;
  events: StoredEvent[];
  samples: Sample[];
}): Promise<Uint8Array> {
  const buffer = new TempBuffer();
  const writer = new McapWriter({ writable: buffer });
  await writer.start({ profile: "", library: "HRIStudio" });
  const channels = new Map<string, number>();
  const channel = async (topic: string, schemaName: string) => {
    const known = channels.get(topic);
    if (known !== undefined) return known;
    const schemaId = await writer.registerSchema({ name: schemaName, encoding: "jsonschema", data: ANY_OBJECT });
    const id = await writer.registerChannel({
      schemaId,
      topic,
      messageEncoding: "json",
      metadata: new Map([["trial_id", trialId]]),
    });
    channels.set(topic, id);
    return id;
  };
  const start = t0.getTime();
  // Events before the start have no time from t0: they are placed at their server time.
  const eventMs = (e: StoredEvent) => (e.relMs === null ? e.serverTime.getTime() - start : e.relMs);
  const messages = [
    ...events.map((e) => ({ ms: eventMs(e), topic: EVENTS_TOPIC, schema: "hristudio.TrialEvent", data: e as object })),
    ...events
      .filter((e) => e.type === "action.dispatched")
      .map((e) => ({ ms: eventMs(e), topic: COMMANDS_TOPIC, schema: "hristudio.RobotCommand", data: e as object })),
    ...samples.map((s) => ({ ms: s.relMs, topic: s.topic, schema: "hristudio.RobotSample", data: s.data })),
  ].sort((a, b) => a.ms - b.ms);
  const sequences = new Map<number, number>();
  const encoder = new TextEncoder();
  for (const m of messages) {
    const channelId = await channel(m.topic, m.schema);
    const sequence = (sequences.get(channelId) ?? 0) + 1;
    sequences.set(channelId, sequence);
    const time = nanoseconds(Math.max(0, start + m.ms));
    await writer.addMessage({
      channelId,
      sequence,
      logTime: time,
      publishTime: time,
      data: encoder.encode(JSON.stringify(m.data)),
    });
  }
  await writer.end();
  return buffer.get();
}
