// The robot as the wizard sees it during a trial: which registered robot,
// whether it is speaking (and what), its gesture, posture and battery, with a
// warning when the battery is low. What the robot does not report is "not
// reported", never guessed.
import { batteryLow, carriedPosture, LOW_BATTERY_PERCENT, type LiveRobotState } from "@/core/robots/live-state";
import { Card } from "@/ui/surface";

export function RobotStatePanel({
  name,
  state,
  notStarted,
}: {
  name: string | undefined;
  state: LiveRobotState | null;
  /** Before the trial starts the wizard is told of a posture the last trial left. */
  notStarted: boolean;
}) {
  const carried = notStarted ? carriedPosture(name, state) : null;
  const unknown = <span className="text-slate-500">not reported</span>;
  return (
    <Card className="p-4 text-sm">
      <h2 className="mb-2 font-semibold">
        Robot
        {name && (
          <span data-testid="robot-name" className="font-normal text-slate-600">
            : {name}
          </span>
        )}
      </h2>
      {state && batteryLow(state) && (
        <p role="alert" data-testid="battery-low" className="mb-2 rounded bg-red-50 px-2 py-1 text-red-800">
          Battery low ({state.battery} %, below {LOW_BATTERY_PERCENT} %): charge the robot before the next session.
        </p>
      )}
      {carried && (
        <p role="status" data-testid="posture-carried" className="mb-2 rounded bg-amber-50 px-2 py-1 text-amber-900">
          {carried}
        </p>
      )}
      <dl className="grid grid-cols-[5.5rem_1fr] gap-y-1">
        <dt className="text-slate-500">Speaking</dt>
        <dd data-testid="robot-speaking">
          {state?.speaking ? `“${state.speaking}”` : state ? <span className="text-slate-500">silent</span> : unknown}
        </dd>
        <dt className="text-slate-500">Gesture</dt>
        <dd data-testid="robot-gesture" className="break-all">
          {state?.gesture ?? unknown}
        </dd>
        <dt className="text-slate-500">Posture</dt>
        <dd data-testid="robot-posture">{state?.posture ?? unknown}</dd>
        <dt className="text-slate-500">Battery</dt>
        <dd data-testid="robot-battery">{state?.battery != null ? `${state.battery} %` : unknown}</dd>
      </dl>
    </Card>
  );
}
