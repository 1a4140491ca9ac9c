// Replays: a finished trial's robot commands sent again, with their timing,
// to the simulated robot. Only ever the simulated robot: a replay moves a
// robot nobody is standing beside to run, so on real hardware it would move
// unannounced, next to whoever is in the room. With no simulated robot on
// this server (a real robot is configured), replays are refused.
// A replay reads the trial's log and writes nothing: no event, no status.
import type { Plugin } from "@/core/plugins";
import { REPLAY_SPEEDS, replaySchedule } from "@/core/trial/replay";
import { REPLAY_TOPIC, type ReplayAnnouncement } from "@/core/robots/robot-state";
import type { ServerMessage } from "@/core/socket/messages";
import type { Database } from "@/store/client";
import { eventsSince } from "@/store/event-store";
import { withdrawnFrom } from "@/store/withdrawn";
import { trialPlugin } from "@/robots/trial-plugin";
import { RosbridgeTransport } from "@/robots/transports/rosbridge";

export type ReplayStatus = Extract<ServerMessage, { type: "replay" }>;
export type ReplayStart = { ok: true; stop: () => void } | { ok: false; reason: string };

/** How often the robot page is reminded that a replay is on, for a page opened in the middle. */
const ANNOUNCE_EVERY_MS = 1000;

export interface Replays {
  /** Starts a replay; `tell` hears each change of it until it ends or is stopped. Replaces any replay already playing. */
  play(
    trialId: string,
    from: { fromMs: number; speed: number },
    tell: (status: ReplayStatus) => void,
  ): Promise<ReplayStart>;
  close(): Promise<void>;
}

export function simulatorReplays(db: Database, simulatorUrl: string | undefined): Replays {
  let robot: RosbridgeTransport | null = null;
  let playing: { stop: (detail: string) => void } | null = null;

  /** The trial's plugin with the simulated robot connected, or why a replay cannot start. */
  async function prepare(trialId: string, speed: number): Promise<Plugin | string> {
    const withdrawn = await withdrawnFrom(db, trialId);
    if (withdrawn) return withdrawn;
    if (!simulatorUrl)
      return "Replay needs the simulated robot; this server has none running (it drives a real robot, and a replay never moves one).";
    if (!(REPLAY_SPEEDS as readonly number[]).includes(speed))
      return `A replay plays at ${REPLAY_SPEEDS.map((s) => `×${s}`).join(", ")}, not ×${speed}.`;
    const chosen = await trialPlugin(db, trialId);
    if (!chosen.ok) return chosen.reason;
    if (!chosen.plugin)
      return `No robot plugin "${chosen.robotId}" is installed, so this trial's robot messages cannot be made again.`;
    robot ??= new RosbridgeTransport({ url: simulatorUrl });
    try {
      await robot.connect();
    } catch {
      return `The simulated robot at ${simulatorUrl} does not answer; the replay did not start.`;
    }
    return chosen.plugin;
  }

  return {
    async play(trialId, { fromMs, speed }, tell) {
      const plugin = await prepare(trialId, speed);
      if (typeof plugin === "string") return { ok: false, reason: plugin };
      const schedule = replaySchedule(plugin, await eventsSince(db, trialId), { fromMs, speed });
      playing?.stop("Another replay took over the simulated robot.");
      const sim = robot!;
      const { commands } = schedule;
      const timers: Array<ReturnType<typeof setTimeout>> = [];
      let sent = 0;
      let positionMs = fromMs;
      const status = (playing: boolean, detail?: string): ReplayStatus => ({
        type: "replay",
        playing,
        fromMs,
        speed,
        positionMs,
        sent,
        total: commands.length,
        skipped: schedule.skipped.map((s) => s.reason),
        ...(detail ? { detail } : {}),
      });
      const announce = (playing: boolean) =>
        sim.publish(REPLAY_TOPIC, "std_msgs/msg/String", {
          data: JSON.stringify({
            trialId,
            playing,
            speed,
            positionMs,
            sent,
            total: commands.length,
          } satisfies ReplayAnnouncement),
        });
      const startedAt = performance.now();
      let done = false;
      const finish = (detail: string) => {
        if (done) return;
        done = true;
        timers.forEach(clearTimeout);
        clearInterval(reminder);
        if (playing === self) playing = null;
        announce(false);
        tell(status(false, detail));
      };
      const self = { stop: finish };
      // Each timer counts from the same start, so one late message never delays the next.
      for (const command of commands)
        timers.push(
          setTimeout(() => {
            void sim.dispatch(command.action, command.parameters);
            sent++;
            positionMs = command.trialMs;
            announce(true);
            tell(status(true));
          }, command.atMs),
        );
      const lastMs = Math.max(0, (schedule.endMs - fromMs) / speed);
      timers.push(setTimeout(() => finish("The replay reached the end of the trial."), lastMs));
      const reminder = setInterval(() => {
        positionMs = Math.max(positionMs, fromMs + (performance.now() - startedAt) * speed);
        announce(true);
      }, ANNOUNCE_EVERY_MS);
      playing = self;
      announce(true);
      tell(status(true));
      return { ok: true, stop: () => finish("Replay stopped.") };
    },
    async close() {
      playing?.stop("The trial runtime is stopping.");
      await robot?.close();
    },
  };
}
