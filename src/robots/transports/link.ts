// What every transport does alike, kept once: its connection status and the
// listeners told of each change, the check of an action's parameters against
// the plugin's schema, its timeout, and the growing pause between tries. A
// transport adds only how it reaches its robot.
import { validateParameters, withDefaults, type PluginAction } from "../../core/plugins";
import type { ConnectionState, DispatchOptions, DispatchOutcome, Health, Transport } from "./transport";

export const DEFAULT_TIMEOUT_MS = 10_000;

export interface Backoff {
  first: number;
  max: number;
}

/** Reconnects: 250 ms doubling to 5 s. */
export const RECONNECT_BACKOFF: Backoff = { first: 250, max: 5000 };

/** The pause before try `tries` (from 0): doubling from the first, never more than the max. */
export const backoffDelay = (tries: number, { first, max }: Backoff) => Math.min(max, first * 2 ** tries);

export const timeoutOf = (action: PluginAction) => action.timeout ?? DEFAULT_TIMEOUT_MS;

/** The parameters checked against the action's schema, its defaults filled in; or the failure to report. */
export function checkedParameters(
  action: PluginAction,
  parameters: Record<string, unknown>,
): { ok: true; parameters: Record<string, unknown> } | { ok: false; outcome: DispatchOutcome } {
  const problems = validateParameters(action.parameterSchema, parameters);
  if (problems.length)
    return { ok: false, outcome: { status: "failed", reason: problems.map((p) => p.message).join("; ") } };
  return { ok: true, parameters: withDefaults(action.parameterSchema, parameters) };
}

/**
 * Why a robot's address cannot be used, or null. Checked before each action: no wait and no retry can mend
 * a record, so even a retryable action fails at once, in these words rather than a client library's.
 */
export function addressProblem(what: string, address: string, schemes: string[]): string | null {
  let url: URL;
  try {
    url = new URL(address);
  } catch {
    return `${what} address "${address}" is not a URL`;
  }
  if (!schemes.includes(url.protocol))
    return `${what} address "${address}" is not a ${schemes.map((s) => `${s}//`).join(" or ")} address`;
  return null;
}

/** The robot was not reached: a retryable action has waited its whole timeout for it; any other fails at once rather than arriving late. */
export function unreached(action: PluginAction, started: number, reason: string): DispatchOutcome {
  return action.retryable ? { status: "timed_out", afterMs: Date.now() - started } : { status: "failed", reason };
}

const pause = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/**
 * A retryable action's wait for its robot: tries `attempt` until it gives a
 * value or the action's deadline passes, backing off between tries.
 */
export async function untilDeadline<T>(
  deadline: number,
  attempt: () => Promise<T | null>,
  backoff: Backoff = { first: 100, max: 1000 },
): Promise<T | null> {
  for (let tries = 0; ; tries++) {
    const value = await attempt();
    const left = deadline - Date.now();
    if (value !== null || left <= 0) return value;
    await pause(Math.min(left, backoffDelay(tries, backoff)));
  }
}

/** A transport's connection status, told to every listener at once; "closed" is final. */
export abstract class LinkedTransport implements Transport {
  protected status: Health = { state: "disconnected", since: Date.now(), attempts: 0, lastHeartbeatMs: null };
  private readonly listeners = new Set<(health: Health) => void>();

  abstract connect(): Promise<void>;
  abstract dispatch(
    action: PluginAction,
    parameters: Record<string, unknown>,
    options?: DispatchOptions,
  ): Promise<DispatchOutcome>;
  abstract close(): Promise<void>;

  /** Robot state comes over rosbridge; the other transports carry commands only. */
  subscribe(..._args: Parameters<Transport["subscribe"]>): () => void {
    return () => {};
  }

  health(): Health {
    return { ...this.status };
  }

  onHealth(listener: (health: Health) => void) {
    this.listeners.add(listener);
    return () => void this.listeners.delete(listener);
  }

  protected setState(state: ConnectionState, reason?: string) {
    if (this.status.state === state || this.status.state === "closed") return;
    this.status = { ...this.status, state, since: Date.now(), reason };
    this.listeners.forEach((listener) => listener(this.health()));
  }

  /** An error the robot's side reported: every listener hears it once, with the state unchanged. */
  protected tell(problem: string) {
    if (this.status.state === "closed") return;
    this.listeners.forEach((listener) => listener({ ...this.health(), problem }));
  }
}
