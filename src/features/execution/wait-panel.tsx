"use client";
// A "Wait for" pending: what the trial waits for the robot to sense (each
// with where it leads), the last things the robot sensed, and the wizard's
// go on, one key away. The log's robot.sensed events are what is shown: the
// page reads what the runtime logged, never the robot directly.
import { type EventNames, eventName } from "@/core/plugins/event-names";
import { awaitedEvents, exitBy } from "@/core/protocol/flow";
import type { ProtocolAction, StoredEvent, TrialProtocol } from "@/core/trial";
import { Button } from "@/ui/button";
import { clockTime } from "@/ui/clock-time";

type Sensed = Extract<StoredEvent<string>, { type: "robot.sensed" }>;

/** How many of the robot's latest observations the panel lists. */
const RECENT = 5;

export function WaitPanel({
  protocol,
  stepIndex,
  wait,
  events,
  names,
  goOn,
}: {
  protocol: TrialProtocol;
  stepIndex: number;
  wait: ProtocolAction;
  events: ReadonlyArray<StoredEvent<string>>;
  names: EventNames;
  goOn: () => void;
}) {
  const recent = events
    .filter((e): e is Sensed => e.type === "robot.sensed")
    .slice(-RECENT)
    .reverse();
  const where = (after: Parameters<typeof exitBy>[2]) => {
    const exit = exitBy(protocol.steps, stepIndex, after);
    return exit.to === "step" ? `“${protocol.steps[exit.index]!.name}”` : "the end of the trial";
  };
  return (
    <section aria-label="Waiting for the robot" className="rounded-lg border-2 border-brand-500 bg-brand-50 p-4">
      <h2 className="font-medium">Waiting for the robot to sense</h2>
      <ul className="mt-2 space-y-1 text-sm">
        {awaitedEvents(wait).map((e) => (
          <li key={e.id}>
            <strong>{eventName(e.event, names)}</strong> → {where(e.after)}
          </li>
        ))}
        {wait.timeLimit && (
          <li>
            nothing in {wait.timeLimit.seconds} s → {where(wait.timeLimit.after)}
          </li>
        )}
      </ul>
      <h3 className="mt-3 text-sm font-medium">Last sensed</h3>
      {recent.length === 0 ? (
        <p className="text-sm text-slate-600">Nothing yet.</p>
      ) : (
        <ul aria-label="Last sensed" className="text-sm">
          {recent.map((e) => (
            <li key={e.seq}>
              {eventName(e.event, names)} <span className="text-slate-600">at {clockTime(new Date(e.at))}</span>
            </li>
          ))}
        </ul>
      )}
      <Button size="lg" className="mt-3 w-full" onClick={goOn}>
        <kbd className="rounded bg-white/20 px-1.5 text-xs">G</kbd> Go on without it
      </Button>
    </section>
  );
}
