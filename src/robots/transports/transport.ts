// The one contract every robot transport keeps (rosbridge, SSH, HTTP,
// simulated). The trial runtime knows only this; which transport is live is
// chosen in one place from the plugin's `transport` field.
import type { PluginAction } from "../../core/plugins";

/** What became of one dispatch; each maps to an action event of the trial log. */
export type DispatchOutcome =
  | { status: "completed"; detail?: Record<string, unknown> }
  | { status: "failed"; reason: string }
  | { status: "timed_out"; afterMs: number };

export type ConnectionState = "connecting" | "connected" | "disconnected" | "closed";

export interface Health {
  state: ConnectionState;
  /** Date.now() of the last change of state. */
  since: number;
  /** Connection attempts since the last successful one. */
  attempts: number;
  /** Round trip of the last heartbeat, in ms. */
  lastHeartbeatMs: number | null;
}

export interface Transport {
  connect(): Promise<void>;
  /** Sends one action with its parameters; resolves within the action's timeout. */
  dispatch(action: PluginAction, parameters: Record<string, unknown>): Promise<DispatchOutcome>;
  /** Robot state for logging; kept across reconnects. Returns a function that stops it. */
  subscribe(topic: string, messageType: string, onMessage: (message: unknown) => void, options?: { throttleRate?: number }): () => void;
  health(): Health;
  /** Called at once on every change of connection state. */
  onHealth(listener: (health: Health) => void): () => void;
  close(): Promise<void>;
}

export const DEFAULT_TIMEOUT_MS = 10_000;

const pause = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/**
 * A retryable action's wait for its robot: tries `attempt` until it gives a
 * value or the action's deadline passes, backing off between tries.
 */
export async function untilDeadline<T>(deadline: number, attempt: () => Promise<T | null>, backoffMs = { first: 100, max: 1000 }): Promise<T | null> {
  for (let tries = 0; ; tries++) {
    const value = await attempt();
    const left = deadline - Date.now();
    if (value !== null || left <= 0) return value;
    await pause(Math.min(left, backoffMs.max, backoffMs.first * 2 ** tries));
  }
}
