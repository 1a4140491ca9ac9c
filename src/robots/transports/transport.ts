// The one contract every robot transport keeps (rosbridge, SSH, HTTP,
// simulated). The trial runtime knows only this; which transport is live is
// chosen in one place from the plugin's `transport` field.
import type { PluginAction, Sent } from "../../core/plugins";

/**
 * What became of one dispatch; each maps to an action event of the trial log. `not_sent`: it never left
 * (too old by the time the link could send it); `unknown`: it left, and the link was lost before an
 * answer, so it may still happen; `failed`: the robot or the transport said it failed.
 */
export type DispatchOutcome =
  | { status: "completed"; detail?: Record<string, unknown> }
  | { status: "failed"; reason: string }
  | { status: "not_sent"; reason: string }
  | { status: "unknown"; reason: string }
  | { status: "timed_out"; afterMs: number };

export interface DispatchOptions {
  /** Date.now() time past which the action is no longer worth sending: a transport that waits for its robot sends nothing after it (not_sent). */
  freshUntil?: number;
  /** After an outcome "unknown": the robot's own later word on it (its done message, once the link is back). */
  later?: (outcome: DispatchOutcome) => void;
  /**
   * What dispatch puts on the wire, told as it is built (before any wait for the link), so the record is the
   * message sent, built once: null when the action sends nothing. Not told when it is refused before that.
   */
  sending?: (sent: Sent | null) => void;
}

export type ConnectionState = "connecting" | "connected" | "disconnected" | "closed";

export interface Health {
  state: ConnectionState;
  /** Date.now() of the last change of state. */
  since: number;
  /** Connection attempts since the last successful one. */
  attempts: number;
  /** Round trip of the last heartbeat, in ms. */
  lastHeartbeatMs: number | null;
  /** Why the link was last lost, in plain words. */
  reason?: string;
  /** An error the robot's side reported (e.g. rosbridge refused a subscription), told once as it comes. */
  problem?: string;
}

export interface Transport {
  connect(): Promise<void>;
  /** Sends one action with its parameters; resolves within the action's timeout. */
  dispatch(
    action: PluginAction,
    parameters: Record<string, unknown>,
    options?: DispatchOptions,
  ): Promise<DispatchOutcome>;
  /**
   * Robot state for logging, or what the robot senses (kind "event": sent only when something happens, so
   * never reported silent); kept across reconnects. Returns a function that stops it.
   */
  subscribe(
    topic: string,
    messageType: string,
    onMessage: (message: unknown) => void,
    options?: { throttleRate?: number; kind?: "state" | "event" },
  ): () => void;
  health(): Health;
  /** Called at once on every change of connection state. */
  onHealth(listener: (health: Health) => void): () => void;
  close(): Promise<void>;
}
