// One live trial in the runtime: the only writer of its event log. Commands
// run one at a time: decide (pure engine) → append (committed) → apply →
// tell every client. Robot and clock reports come back as commands too.
import {
  applyAll,
  decide,
  fold,
  type Command,
  type EngineEvent,
  type StoredEvent,
  type TrialProtocol,
  type TrialState,
} from "@/core/trial";
import type { Database } from "@/store/client";
import { appendEvents, eventsSince } from "@/store/event-store";
import { CONTROL_TYPES } from "@/core/trial/types";
import type { RobotLink } from "./robot";
import { sampleRecorder } from "./samples";

function startedAt(events: StoredEvent[]): number | null {
  const started = events.find((e) => e.type === "trial.started");
  return started ? started.serverTime.getTime() : null;
}

export type CommandResult = { ok: true; events: StoredEvent[] } | { ok: false; reason: string };

const BLOCKS_WITHOUT_ROBOT = new Set<string>(CONTROL_TYPES);

/**
 * How long the trial log may take to answer before the wizard's commands are
 * refused rather than held: a command carried out late (a line spoken 17 s
 * after it was asked for, in the middle of something else) is worse than one
 * refused plainly and asked again. Three seconds, not one: a database busy
 * with a backup or a heavy export can take more than a second to commit, and
 * a line dropped then is a false alarm; a dead one refuses at once anyway
 * (its connection is refused).
 */
const LOG_DEADLINE_MS = 3000;
const LOG_UNAVAILABLE =
  "The trial log is not answering (the database is unavailable), so nothing was done and the robot was not told. Try again in a moment.";

const NOT_CARRIED_OUT = "Not carried out: the robot was stopped after you asked for this.";
const NOT_SENT = {
  stopped: "Not sent: the robot was stopped before this reached it.",
  late: "Not sent: the trial log answered too late, so this would have reached the robot late.",
} as const;

/** What the robot side and the clock report, and the stops: logged whenever the log can take them, never refused for lateness. */
const ALWAYS_LOGGED = new Set<Command["kind"]>([
  "dispatched",
  "completed",
  "failed",
  "timed_out",
  "emergency_stop",
  "abort",
]);

/** The wizard's commands that can set the robot going: after a stop, one asked for before it is stale. */
const MOVES_THE_ROBOT = new Set<Command["kind"]>([
  "start",
  "next",
  "trigger",
  "answer",
  "jump",
  "unscripted",
  "resume",
]);

export class TrialHost {
  private state: TrialState;
  private queue: Promise<unknown> = Promise.resolve();
  private readonly listeners = new Set<(events: StoredEvent[]) => void>();
  private shut = false;
  /** How many times the robot was stopped outside the queue: commands asked for before a stop are dropped. */
  private halts = 0;
  /** When the command being logged now started its write: null while none is. */
  private writingSince: number | null = null;
  /** Told when the trial ends, and when its last client leaves. */
  private readonly lifecycle = { ended: () => {}, unwatched: () => {} };
  private readonly timers = new Set<ReturnType<typeof setTimeout>>();
  /** Sounds handed to the wizard's browser to play, by action id, until it reports their end. */
  private readonly browserPlays = new Set<string>();
  private readonly samples;
  private readonly stopWatching: () => void;
  /** The trial's t0, once started: samples are timed from it. */
  private t0: number | null;

  private constructor(
    private readonly db: Database,
    readonly trialId: string,
    readonly protocol: TrialProtocol,
    private readonly robot: RobotLink,
    history: StoredEvent[],
  ) {
    this.state = fold(protocol, history);
    this.t0 = startedAt(history);
    this.samples = sampleRecorder(db, trialId, (error) =>
      console.error(`[runtime] trial ${trialId}: samples not stored: ${String(error)}`),
    );
    this.stopWatching = robot.watchState((topic, message) => {
      const live = this.state.status === "in_progress" || this.state.status === "paused";
      if (live && this.t0 !== null) this.samples.add(topic, Date.now() - this.t0, message);
    });
  }

  /** Rebuilds the trial from its events; actions cut off by a restart are marked failed. */
  static async open(db: Database, trialId: string, protocol: TrialProtocol, robot: RobotLink) {
    const host = new TrialHost(db, trialId, protocol, robot, await eventsSince(db, trialId));
    const interrupted = Object.entries(host.state.actions).filter(
      ([, a]) => a.status === "requested" || a.status === "running",
    );
    for (const [actionId] of interrupted) {
      await host.command(
        { kind: "failed", actionId, reason: "The trial runtime restarted while this action was running." },
        null,
      );
    }
    return host;
  }

  /** Whether the robot is reachable now, and a listener for every change. */
  robotStatus() {
    return this.robot.connected();
  }

  onRobotStatus(listener: (connected: boolean, detail?: string) => void) {
    this.robot.onConnection(listener);
  }

  get current(): TrialState {
    return this.state;
  }

  subscribe(listener: (events: StoredEvent[]) => void) {
    this.listeners.add(listener);
    return () => {
      if (this.listeners.delete(listener) && this.listeners.size === 0) this.lifecycle.unwatched();
    };
  }

  /** `ended`: the trial completed or was aborted; `unwatched`: no client follows it any more. */
  onLifecycle(handlers: { ended: () => void; unwatched: () => void }) {
    Object.assign(this.lifecycle, handlers);
  }

  /** Whether the host has closed: it runs nothing any more. */
  get closed(): boolean {
    return this.shut;
  }

  /** Whether any client follows the trial. */
  get watched(): boolean {
    return this.listeners.size > 0;
  }

  /** Whether an action is under way: closing now would cut it off. */
  get busy(): boolean {
    return Object.values(this.state.actions).some((a) => a.status === "requested" || a.status === "running");
  }

  /**
   * Runs after every earlier command has finished, so the log never forks.
   * An emergency stop or abort first stops the robot, at once, ahead of every
   * command waiting to be logged: safety before logging. Its own entry is
   * logged after, in turn; what was asked for before it and has not reached
   * the robot is dropped (see `overtaken`), never sent after it.
   */
  command(command: Command, actorId: string | null): Promise<CommandResult> {
    if (command.kind === "emergency_stop" || command.kind === "abort") {
      this.halts++;
      this.robot.halt();
    }
    const halts = this.halts;
    const asked = Date.now();
    // The log is stuck on an earlier command: refuse now rather than queue behind it.
    if (!ALWAYS_LOGGED.has(command.kind) && this.writingSince !== null && asked - this.writingSince > LOG_DEADLINE_MS)
      return Promise.resolve({ ok: false, reason: LOG_UNAVAILABLE });
    const run = this.queue.then(() => this.execute(command, actorId, halts, asked));
    this.queue = run.catch(() => undefined);
    return run;
  }

  private async execute(
    command: Command,
    actorId: string | null,
    halts: number,
    asked: number,
  ): Promise<CommandResult> {
    // A robot's late report, or a clock, after the host closed: the trial is no longer run from here.
    if (this.shut) return { ok: false, reason: "This trial is no longer open here. Reload the page." };
    const before = this.overtaken(command, halts, asked);
    if (before) return { ok: false, reason: before === "stopped" ? NOT_CARRIED_OUT : LOG_UNAVAILABLE };
    const decision = decide(this.protocol, this.state, command);
    if (!decision.ok) return decision;
    const cursor = { id: this.trialId, lastSeq: this.state.lastSeq, t0: this.t0 === null ? null : new Date(this.t0) };
    this.writingSince = Date.now();
    const stored = await appendEvents(this.db, cursor, decision.events, actorId)
      .catch((error: unknown) => this.landedAnyway(error))
      .finally(() => {
        this.writingSince = null;
      });
    this.state = applyAll(this.state, stored);
    this.t0 ??= startedAt(stored);
    for (const listener of this.listeners) listener(stored);
    // Stopped, or the log answered too late, while this was being logged: it is in the log as asked
    // for, and goes no further.
    const after = this.overtaken(command, halts, asked);
    if (after) this.withhold(decision.events, NOT_SENT[after]);
    else this.carryOut(decision.events);
    if (this.state.status === "completed" || this.state.status === "aborted") this.lifecycle.ended();
    return { ok: true, events: stored };
  }

  /** Whether a command was overtaken since it was asked for: by a stop, or by the log's deadline. */
  private overtaken(command: Command, halts: number, asked: number): "stopped" | "late" | null {
    if (halts !== this.halts && MOVES_THE_ROBOT.has(command.kind)) return "stopped";
    if (!ALWAYS_LOGGED.has(command.kind) && Date.now() - asked > LOG_DEADLINE_MS) return "late";
    return null;
  }

  /**
   * An append that failed may still have committed, its reply lost with the
   * connection. Only this host writes the trial (it holds the lock), so
   * events past the last sequence number are this command's own: take them
   * as its outcome rather than write them again or stall on a stale cursor.
   */
  private async landedAnyway(error: unknown): Promise<StoredEvent[]> {
    const landed = await eventsSince(this.db, this.trialId, this.state.lastSeq).catch(() => []);
    if (landed.length === 0) throw error;
    return landed;
  }

  /** Each action held back is logged as failed, with why, so the log says it never reached the robot. */
  private withhold(events: EngineEvent[], reason: string) {
    for (const event of events)
      if (event.type === "action.requested")
        void this.command({ kind: "failed", actionId: event.actionId, reason }, null);
  }

  /** What happens in the world once the events are committed. */
  private carryOut(events: EngineEvent[]) {
    for (const event of events) {
      if (event.type !== "action.requested") continue;
      const report = (command: Command) => {
        if (command.kind === "dispatched" && command.detail?.playedBy === "browser")
          this.browserPlays.add(command.actionId);
        void this.command(command, null);
      };
      if (event.actionType === "pause") {
        // The clock starts once "dispatched" is stored, so the logged hold is never shorter than designed.
        const seconds = Number(event.parameters.seconds ?? 0);
        void this.command({ kind: "dispatched", actionId: event.actionId }, null).then(() => {
          const timer = setTimeout(() => {
            this.timers.delete(timer);
            report({ kind: "completed", actionId: event.actionId, detail: { heldMs: seconds * 1000 } });
          }, seconds * 1000);
          this.timers.add(timer);
        });
      } else if (!BLOCKS_WITHOUT_ROBOT.has(event.actionType)) {
        this.robot.perform(
          { actionId: event.actionId, actionType: event.actionType, parameters: event.parameters },
          report,
        );
      }
    }
  }

  /**
   * The wizard's browser finished a sound the robot could not play (or could
   * not play it): logged as the action's end, by the wizard who heard it.
   * Only a sound handed to the browser ends this way, never a robot's action.
   */
  browserPlayed(actionId: string, failed: string | undefined, actorId: string | null): Promise<CommandResult> {
    if (!this.browserPlays.delete(actionId))
      return Promise.resolve({ ok: false, reason: "No sound of this trial is waiting for the browser to play it." });
    return this.command(
      failed
        ? { kind: "failed", actionId, reason: `The wizard's browser could not play the sound: ${failed}` }
        : { kind: "completed", actionId, detail: { playedBy: "browser" } },
      actorId,
    );
  }

  async close() {
    this.shut = true;
    for (const t of this.timers) clearTimeout(t);
    this.stopWatching();
    await this.queue;
    await this.samples.close();
    this.robot.close();
  }
}
