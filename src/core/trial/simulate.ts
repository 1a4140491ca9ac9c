// Runs commands through the engine without any I/O, as a runtime would:
// rejected commands write nothing. For tests, pilots and reports.
import { decide } from "./decide";
import { fold } from "./fold";
import type { Command, EngineEvent, TrialEvent, TrialProtocol } from "./types";

export interface Simulation {
  log: TrialEvent[];
  /** What the last command produced, or why it was refused. */
  last: EngineEvent[] | string;
}

/** `clock(i)` gives the relMs of the i-th stored event (default: 10 ms apart). */
export function simulate(
  protocol: TrialProtocol,
  commands: Command[],
  clock: (i: number) => number = (i) => i * 10,
): Simulation {
  const log: TrialEvent[] = [];
  let last: EngineEvent[] | string = [];
  for (const command of commands) {
    const decision = decide(protocol, fold(protocol, log), command);
    last = decision.ok ? decision.events : decision.reason;
    if (decision.ok) for (const e of decision.events) log.push({ ...e, seq: log.length + 1, relMs: clock(log.length) });
  }
  return { log, last };
}
