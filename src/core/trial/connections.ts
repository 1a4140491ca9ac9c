// What the wizard's page says of the three things a live trial stands on:
// its connection to the trial runtime, the robot (as the runtime last said)
// and the database (as the web app last found it). Each is shown as it is:
// while the runtime is away nothing it said earlier about the robot still
// holds, so the robot is unknown, not "connected". A runtime that is
// connected but has stopped answering the page's heartbeat (a frozen process
// keeps its sockets open) is "not answering": as good as away.
import type { RuntimeLink } from "@/core/socket/heartbeat";

export type Tone = "green" | "amber" | "red" | "slate";
/** The database as the page's last question to the web app found it. */
export type DatabaseState = "connected" | "unavailable" | "checking";

export interface Indicator {
  what: "runtime" | "robot" | "database";
  /** One or a few words: "live", "connected (camera refused)", "unavailable". */
  state: string;
  tone: Tone;
}

/** The page's connection to the trial runtime: answering, connected but silent, or being made again. */
export type RuntimeState = RuntimeLink | "reconnecting";

export interface Connections {
  runtime: RuntimeState;
  /** As the runtime last said; null while it has said nothing of a robot. */
  robot: { connected: boolean; detail?: string } | null;
  database: DatabaseState;
  /** The trial has ended: its robot link was closed on purpose, so its absence is no alarm. */
  ended?: boolean;
}

function robotIndicator(c: Connections): Indicator | null {
  if (c.runtime !== "live") return c.robot ? { what: "robot", state: "unknown", tone: "slate" } : null;
  if (!c.robot) return null;
  const detail = c.robot.detail ? ` (${c.robot.detail})` : "";
  // A connected robot's detail is an error its side reported (e.g. a refused subscription): shown, not hidden.
  if (c.robot.connected) return { what: "robot", state: `connected${detail}`, tone: detail ? "amber" : "green" };
  if (c.ended) return { what: "robot", state: "released", tone: "slate" };
  return { what: "robot", state: `disconnected${detail}`, tone: "red" };
}

export function indicators(c: Connections): Indicator[] {
  const robot = robotIndicator(c);
  return [
    {
      what: "runtime",
      state: c.runtime === "silent" ? "not answering" : c.runtime,
      tone: c.runtime === "live" ? "green" : "red",
    },
    ...(robot ? [robot] : []),
    {
      what: "database",
      state: c.database,
      tone: c.database === "connected" ? "green" : c.database === "unavailable" ? "red" : "slate",
    },
  ];
}
