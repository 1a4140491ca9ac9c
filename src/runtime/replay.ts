// Replays: a finished trial's robot commands sent again, with their timing,
// to a simulated robot. Only ever a simulated robot: a replay moves a robot
// nobody is standing beside to run, so on real hardware it would move
// unannounced, next to whoever is in the room. With no simulated robot on
// this server (a real robot is configured), replays are refused.
// A replay takes its robot the way a trial does: one available to the trial's
// study, and never one a live trial, a trial starting or another replay holds
// (`RobotClaims`, in any runtime process); it holds it until it ends.
// A replay reads the trial's log and writes nothing: no event, no status.
import { REPLAY_SPEEDS, replaySchedule } from "@/core/trial/replay";
import { REPLAY_TOPIC, type ReplayAnnouncement } from "@/core/robots/robot-state";
import { replayBusy } from "@/core/robots/registry";
import type { ServerMessage } from "@/core/socket/messages";
import type { Database } from "@/store/client";
import { eventsSince } from "@/store/event-store";
import { withdrawnFrom } from "@/store/withdrawn";
import { drivenByLiveTrial, simulatedRobotsFor, type RobotRecord } from "@/robots/registry";
import { trialPlugin } from "@/robots/trial-plugin";
import { RosbridgeTransport } from "@/robots/transports/rosbridge";
import type { RobotClaims } from "./robot-claims";

export type ReplayStatus = Extract<ServerMessage, { type: "replay" }>;
export type ReplayStart = { ok: true; stop: () => void } | { ok: false; reason: string };

/** How often the robot page is reminded that a replay is on, for a page opened in the middle. */
const ANNOUNCE_EVERY_MS = 1000;

export interface Replays {
  /** Starts a replay; `tell` hears each change of it until it ends or is stopped. Refused while its robot is busy. */
  play(
    trialId: string,
    from: { fromMs: number; speed: number },
    tell: (status: ReplayStatus) => void,
  ): Promise<ReplayStart>;
  close(): Promise<void>;
}

const NO_SIMULATOR =
  "Replay needs the simulated robot; this server has none running (it drives a real robot, and a replay never moves one).";
const NONE_FOR_STUDY =
  "No simulated robot is available to this study, so the replay did not start: an administrator makes one available (Administration → Robots).";

interface Taken {
  robot: RobotRecord;
  release: () => void;
  /** Told when another runtime process took the robot meanwhile (this one lost its claim). */
  onLost: (listener: () => void) => void;
}

export function simulatorReplays(db: Database, claims: RobotClaims): Replays {
  /** One connection per simulated robot, kept for the next replay on it. */
  const links = new Map<string, RosbridgeTransport>();
  /** How to stop each replay playing here. */
  const replaying = new Set<(detail: string) => void>();

  /** The first of the simulated robots that nothing holds, claimed; or why there is none. */
  async function takeRobot(available: RobotRecord[]): Promise<Taken | string> {
    let busy: string | null = null;
    for (const robot of available) {
      let lost = () => {};
      const claim = await claims.take(robot.id, "replay", () => lost());
      if (!claim.ok) {
        busy ??= replayBusy(robot.name, claim.holder);
        continue;
      }
      // Claimed first, then looked at: a trial starting on it now is refused the claim, or is seen live here.
      let live: boolean;
      try {
        live = await drivenByLiveTrial(db, robot.id);
      } catch (error) {
        claim.release();
        throw error;
      }
      if (!live) return { robot, release: claim.release, onLost: (listener) => (lost = listener) };
      claim.release();
      busy ??= replayBusy(robot.name, "live trial");
    }
    return busy!;
  }

  /** The trial's plugin with a simulated robot claimed and connected, or why a replay cannot start. */
  async function prepare(trialId: string, speed: number) {
    const withdrawn = await withdrawnFrom(db, trialId);
    if (withdrawn) return withdrawn;
    const chosen = await trialPlugin(db, trialId);
    if (!chosen.ok) return chosen.reason;
    const { available, any } = await simulatedRobotsFor(db, trialId, chosen.robotId);
    if (!available.length) return any ? NONE_FOR_STUDY : NO_SIMULATOR;
    if (!(REPLAY_SPEEDS as readonly number[]).includes(speed))
      return `A replay plays at ${REPLAY_SPEEDS.map((s) => `×${s}`).join(", ")}, not ×${speed}.`;
    if (!chosen.plugin)
      return `No robot plugin "${chosen.robotId}" is installed, so this trial's robot messages cannot be made again.`;
    const taken = await takeRobot(available);
    if (typeof taken === "string") return taken;
    const url = taken.robot.rosbridgeUrl!;
    let sim = links.get(url);
    if (!sim) links.set(url, (sim = new RosbridgeTransport({ url })));
    try {
      await sim.connect();
    } catch {
      taken.release();
      return `The simulated robot "${taken.robot.name}" does not answer; the replay did not start.`;
    }
    return { plugin: chosen.plugin, sim, ...taken };
  }

  return {
    async play(trialId, { fromMs, speed }, tell) {
      const prepared = await prepare(trialId, speed);
      if (typeof prepared === "string") return { ok: false, reason: prepared };
      const { plugin, sim, release, onLost } = prepared;
      let schedule: ReturnType<typeof replaySchedule>;
      try {
        schedule = replaySchedule(plugin, await eventsSince(db, trialId), { fromMs, speed });
      } catch (error) {
        release();
        throw error;
      }
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
        replaying.delete(finish);
        announce(false);
        release();
        tell(status(false, detail));
      };
      onLost(() => finish("Another trial runtime took the simulated robot; the replay stopped."));
      // Each timer counts from the same start, so one late message never delays the next.
      for (const command of commands)
        timers.push(
          setTimeout(() => {
            // A dispatch that throws (a plugin the simulator cannot map) ends this replay, never the runtime.
            sim
              .dispatch(command.action, command.parameters)
              .catch(() =>
                finish("The simulated robot could not take one of the trial's actions; the replay stopped."),
              );
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
      replaying.add(finish);
      announce(true);
      tell(status(true));
      return { ok: true, stop: () => finish("Replay stopped.") };
    },
    async close() {
      for (const stop of replaying) stop("The trial runtime is stopping.");
      for (const link of links.values()) await link.close();
    },
  };
}
