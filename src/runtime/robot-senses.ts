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
      // A topic that reports all along (a sonar) is read at its declared rate: fifty robots' sonars at full rate cost
      // the other trials' tail (bench/trial-latency, 50 × 10 paced: p99 110–157 ms, 62–96 ms at 200 ms). The slowest
      // rate its events allow, and none if one of them leaves it out (a touch: no press may be missed).
      { kind: "event", ...throttleOf(events) },
    ),
  );
  return () => stops.forEach((stop) => stop());
}

function throttleOf(events: RobotEvent[]): { throttleRate?: number } {
  const rates = events.map((e) => e.throttleRate ?? 0);
  const rate = Math.min(...rates);
  return rate > 0 ? { throttleRate: rate } : {};
}
