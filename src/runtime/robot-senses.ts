// What the trial's robot senses, as it happens: each event its plugin
// declares is watched on its topic over the trial's robot connection, every
// message matched against the event's condition (senses.ts), and each match
// handed on as a Sensed, timed by the robot's own stamp when the message has
// one, else by the runtime's clock. Nothing here decides what a match does.
import {
  messageTime,
  type Plugin,
  type RobotEvent,
  type SenseState,
  type Sensed,
  sense,
  UNSENSED,
} from "@/core/plugins";
import type { Transport } from "@/robots/transports";

/**
 * How often a distance is read: a sonar or a laser reports all along (10 Hz or
 * more) whether anyone is near or not, and every reading crosses the link and
 * is matched. A fifth of a second is finer than any "for a time" a study sets;
 * at full rate fifty robots' sonars cost the other trials' commands their tail
 * (bench/trial-latency, 50 trials × 10 observers paced, quiet machine: p99
 * 110–157 ms with every reading, 62–96 ms with five a second, about 40 ms with
 * none). A touch or a heard word is never thinned.
 */
export const DISTANCE_READING_MS = 200;

/** Watches every declared event until the returned function is called. */
export function watchSenses(
  transport: Pick<Transport, "subscribe">,
  plugin: Plugin,
  onSensed: (sensed: Sensed) => void,
  now: () => number = Date.now,
): () => void {
  const states = new Map<string, SenseState>();
  // One subscription per topic: a head's three sensors share theirs.
  const byTopic = new Map<string, RobotEvent[]>();
  for (const event of plugin.events ?? []) {
    const key = `${event.topic} ${event.messageType}`;
    byTopic.set(key, [...(byTopic.get(key) ?? []), event]);
  }
  const stops = [...byTopic.values()].map((events) =>
    transport.subscribe(
      events[0]!.topic,
      events[0]!.messageType,
      (message) => {
        const at = messageTime(message, now());
        for (const event of events) {
          const step = sense(event, states.get(event.id) ?? UNSENSED, message, at);
          states.set(event.id, step.state);
          if (step.sensed) onSensed(step.sensed);
        }
      },
      // A touch topic is quiet until someone touches: its silence is no fault to report.
      {
        kind: "event",
        ...(events.every((e) => e.when.kind === "near") ? { throttleRate: DISTANCE_READING_MS } : {}),
      },
    ),
  );
  return () => stops.forEach((stop) => stop());
}
