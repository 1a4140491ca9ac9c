// The trial runtime's view of a robot: perform an action and report back
// through the same commands a wizard's reports would use. Transports (issue:
// robots) implement it; nothing else in the runtime knows which is live.
export interface RobotRequest {
  actionId: string;
  actionType: string;
  parameters: Record<string, unknown>;
}

export type RobotReport =
  | { kind: "dispatched"; actionId: string; detail?: Record<string, unknown> }
  | { kind: "completed"; actionId: string; detail?: Record<string, unknown> }
  | { kind: "failed"; actionId: string; reason: string }
  | { kind: "timed_out"; actionId: string };

export interface RobotLink {
  perform(request: RobotRequest, report: (r: RobotReport) => void): void;
  /** Stop everything now (emergency stop). */
  halt(): void;
  connected(): boolean;
  onConnection(listener: (connected: boolean, detail?: string) => void): void;
  close(): void;
}

/**
 * A robot that only keeps time: every action completes after its duration.
 * Used for rehearsals without a robot plugin transport, and in engine tests.
 */
export function timekeeperRobot(durationMs: (r: RobotRequest) => number = () => 0): RobotLink {
  const timers = new Set<ReturnType<typeof setTimeout>>();
  return {
    perform(request, report) {
      report({ kind: "dispatched", actionId: request.actionId });
      const timer = setTimeout(() => {
        timers.delete(timer);
        report({ kind: "completed", actionId: request.actionId });
      }, durationMs(request));
      timers.add(timer);
    },
    halt() {
      for (const t of timers) clearTimeout(t);
      timers.clear();
    },
    connected: () => true,
    onConnection() {},
    close() {
      this.halt();
    },
  };
}
