// One live trial in the runtime: the only writer of its event log. Commands
// run one at a time: decide (pure engine) → append (committed) → apply →
// tell every client. Robot and clock reports come back as commands too.
import {
  applyInPlace,
  decideAfterReports,
  decideReports,
  fold,
  haltsTheRobot,
  type Command,
  type EngineEvent,
  type StoredEvent,
  type TrialProtocol,
  type TrialState,
} from "@/core/trial";
import { type Database, neverReachedDatabase } from "@/store/client";
import { answeredRequests, eventPages, eventsSince, fencedOut, type TrialCursor } from "@/store/event-store";
import { directWriter, type LogWriter } from "./log-writer";
import { logUnexpected } from "@/store/error-reference";
import { areTheseEvents } from "@/core/trial/landed";
import { CONTROL_TYPES } from "@/core/trial/types";
import { droppedReason, staleness } from "@/core/trial/freshness";
import type { CameraFrame, RobotLink, RobotReport } from "./robot";
import { type EventNames, NO_EVENT_NAMES } from "@/core/plugins/event-names";
import type { Sensed } from "@/core/plugins/types";
import { type SampleRecorder, type SampleWriter, sampleWriter } from "./samples";
import { TrialTimers } from "./trial-timers";
import { foldLiveState, UNKNOWN_STATE, type LiveRobotState } from "@/core/robots/live-state";

function startedAt(events: StoredEvent[]): number | null {
  const started = events.find((e) => e.type === "trial.started");
  return started ? started.serverTime.getTime() : null;
}

export type CommandResult = { ok: true; seqs: number[] } | { ok: false; reason: string };

/**
 * The ownership a host writes under: its epoch (`takeTrial`), whom to tell once another process took the
 * trial, and whether this process still holds it (`TrialLocks.owns`, what each send to the robot waits on).
 */
export interface Ownership {
  epoch: number;
  lost: () => void;
  owns: () => Promise<boolean>;
}

/**
 * A wizard's request: its id is the command's idempotency key; `retry` asks again after a dropped connection;
 * `askedAt`, when the wizard asked, on this process's clock (src/core/trial/freshness.ts).
 */
export interface Request {
  id: string;
  retry?: boolean;
  askedAt?: number;
}

const BLOCKS_WITHOUT_ROBOT = new Set<string>(CONTROL_TYPES);

/** An action the robot link is asked to carry out once logged (a pause is held by the host itself). */
const sentToRobot = (event: EngineEvent) =>
  event.type === "action.requested" && event.actionType !== "pause" && !BLOCKS_WITHOUT_ROBOT.has(event.actionType);

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

const NOT_ANSWERED =
  "The trial log did not answer in time (the database may be down or overloaded), so the robot was not told. Should the log take this late, it appears there with its robot actions marked not sent: check the log before asking again.";

const STOP_NOT_LOGGED =
  "The robot was stopped, but the trial log is not answering (the database is unavailable), so the stop is not in it.";
const STOP_UNCONFIRMED =
  "The robot was stopped, but the trial log did not confirm the stop: should it take it late, it appears there.";
const LOG_MOVED =
  "Not carried out: an earlier command reached the trial log late and is shown there now. Check the log before asking again.";

const TAKEN_OVER =
  "Not carried out: another runtime process took this trial over a moment ago, so nothing was logged and the robot was not told. Ask again: it goes to that process.";

const NEVER_ARRIVED =
  "Not carried out: the connection dropped before this reached the trial. Ask again if you still want it.";

const NOT_CARRIED_OUT = "Not carried out: the robot was stopped after you asked for this.";
const NOT_SENT = {
  stopped: "Not sent: the robot was stopped before this reached it.",
  late: "Not sent: the trial log answered too late, so this would have reached the robot late.",
  takenOver: "Not sent: another runtime process took this trial over as this was logged, so the robot was not told.",
} as const;

const TAKEN_OVER_AS_LOGGED =
  "Not carried out: another runtime process took this trial over as this was logged, so the robot was not told. Ask again: it goes to that process.";

/** Where a command too old is dropped before the robot link: the runtime's queue (a resumed process's too). */
const QUEUE = "the runtime's queue";

/** What the robot side and the clock report, and the stops: logged whenever the log can take them, never refused for lateness. */
const ALWAYS_LOGGED = new Set<Command["kind"]>([
  "dispatched",
  "completed",
  "failed",
  "not_sent",
  "unknown",
  "timed_out",
  "emergency_stop",
  "abort",
  "robot_problem",
  "timer_fired",
  "sensed",
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

/**
 * The wizard is answered by the log's deadline, even when the write under way
 * never returns (a connection caught by a restart of the database): past it,
 * the write, if it lands at all, is marked "not sent" (see `overtaken`). The
 * margin keeps the two on the same side of the deadline.
 */
const DEADLINE_MARGIN_MS = 250;

const RESTARTED =
  "The trial runtime restarted while this action was under way: it may have reached the robot and been done.";

/**
 * Commands given back to back: each came within this long of the answer to the one before it, faster than a
 * person reacts to what the screen shows (a tool, a test, a bench; a wizard clicking twice comes before the
 * answer). While the wizard's commands come so, the robot's reports wait for the next; at a human pace
 * they are logged at once, at the time they came.
 */
const BACK_TO_BACK_MS = 100;

/**
 * How long the robot's reports wait for the next of a wizard's commands given back to back, whose append
 * carries them: the next line comes a moment after the last one's answer, as the robot reports its
 * dispatch, and one commit then carries both, where two in turn held the next line back. At 2 ms a line
 * slower than that still met its reports' commit under way now and then (the queue's wait p99 1.0-1.4 ms,
 * 0.04 at 5).
 */
const REPORTS_WAIT_MS = 5;

/** A timer this late means the process itself was stalled (frozen, or starved of the processor). */
const STALL_SLACK_MS = 1000;

/**
 * Events read and folded at a time when a trial opens: a few milliseconds of work each, as the
 * runtime's engine runs it (src/launcher/runtime-engine.ts), so the other trials' commands wait no longer.
 */
const OPENING_PAGE = 1000;

function answeredBy(run: Promise<CommandResult>, at: number): Promise<CommandResult> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const late = new Promise<CommandResult>((resolve) => {
    timer = setTimeout(() => resolve({ ok: false, reason: NOT_ANSWERED }), Math.max(0, at - Date.now()));
  });
  return Promise.race([run, late]).finally(() => clearTimeout(timer));
}

export class TrialHost {
  private readonly state: TrialState;
  private queue: Promise<unknown> = Promise.resolve();
  /** Each client's listener, and what it does once this host closes (follow the trial from elsewhere). */
  private readonly listeners = new Map<(events: StoredEvent[]) => void, () => void>();
  private shut = false;
  /** Another process took the trial after this host did: this one writes and sends nothing more. */
  private fenced = false;
  /** How many times the robot was stopped outside the queue: commands asked for before a stop are dropped. */
  private halts = 0;
  /** Whether the write under way has outlasted the log's deadline while this process ran (see `watchWrite`). */
  private logStuck = false;
  /** Who watches the robot's camera now; the camera is subscribed only while someone does. */
  private readonly cameraWatchers = new Set<(frame: CameraFrame) => void>();
  private stopCamera: (() => void) | null = null;
  /** Told when the trial ends, and when its last client leaves. */
  private readonly lifecycle = { ended: () => {}, unwatched: () => {} };
  private readonly timers = new Set<ReturnType<typeof setTimeout>>();
  /** The protocol's time limits, fired as the clock's commands; the engine refuses one the wizard beat. */
  private readonly limits = new TrialTimers((timerId) => void this.command({ kind: "timer_fired", timerId }, null));
  /** Sounds handed to the wizard's browser to play, by action id, until it reports their end. */
  private readonly browserPlays = new Set<string>();
  private readonly samples: SampleRecorder;
  private readonly stopWatching: () => void;
  private readonly stopSensing: () => void;
  /** The trial's t0, once started: samples are timed from it. */
  private t0: number | null;
  /** The log as read to open the trial, kept up to date, until the hello that opened it takes it. */
  private opening: StoredEvent[] | null;
  /** The robot's reports waiting for their append to be made up (a command's, or their own): any that come before it is, join it. */
  private reports: RobotReport[] | null = null;
  /** When the reports waiting stop waiting for a command and go in their own append. */
  private reportsDue: ReturnType<typeof setTimeout> | undefined;
  /**
   * The wizard's commands not yet answered, when the last was, and whether the latest came back to back:
   * before the one ahead of it was answered, or within BACK_TO_BACK_MS of its answer.
   */
  private readonly pace = { waiting: 0, answeredAt: Number.NEGATIVE_INFINITY, backToBack: false };
  /** Each request's outcome by its id, so a request sent again is answered, never carried out twice. */
  private readonly requests = new Map<string, Promise<CommandResult>>();
  /** What the wizard sees of the robot now (speaking, gesture, posture, battery), and who is told of changes. */
  private live: LiveRobotState = UNKNOWN_STATE;
  private readonly liveListeners = new Set<(state: LiveRobotState) => void>();
  /** The registered robot's name, shown to the wizard before the trial starts. */
  robotName: string | null = null;
  /** The plugin's names of its robot's events, for the wizard's refusals ("Head touched", not head_touched). */
  eventNames: EventNames = NO_EVENT_NAMES;
  /** Wraps the start: the runtime refuses one whose robot another live trial drives (trial-hosts.ts). */
  private startGuard = (start: () => Promise<CommandResult>) => start();

  private constructor(
    private readonly db: Database,
    readonly trialId: string,
    readonly protocol: TrialProtocol,
    private readonly robot: RobotLink,
    history: StoredEvent[],
    state: TrialState,
    private readonly log: LogWriter,
    private readonly ownership: Ownership | null,
    samples: SampleWriter,
  ) {
    this.state = state;
    this.t0 = startedAt(history);
    this.opening = history;
    this.samples = samples.recorder(trialId);
    // What the robot's side reports goes in the log, for the analysis and the exports; the same one told again in a row, once.
    let lastProblem: string | null = null;
    robot.onProblem((text) => {
      if (text === lastProblem || this.shut) return;
      lastProblem = text;
      void this.command({ kind: "robot_problem", text }, null);
    });
    this.stopWatching = robot.watchState((topic, message) => {
      const live = this.state.status === "in_progress" || this.state.status === "paused";
      if (live && this.t0 !== null) this.samples.add(topic, Date.now() - this.t0, message);
      const next = foldLiveState(this.live, topic, message);
      if (next === this.live) return;
      this.live = next;
      for (const listener of this.liveListeners) listener(next);
    });
    // What the robot senses moves a waiting trial; before the start and after the end it is not the trial's.
    this.stopSensing = robot.watchSenses((sensed) => {
      const live = this.state.status === "in_progress" || this.state.status === "paused";
      if (live && !this.shut) void this.sensed(sensed);
    });
  }

  /** Rebuilds the trial from its events; actions cut off by a restart are marked sent, outcome unknown. */
  static async open(
    db: Database,
    trialId: string,
    protocol: TrialProtocol,
    robot: RobotLink,
    log: LogWriter = directWriter(db),
    /** Null for a host that is no process's owner (tests, tools): its appends are not fenced. */
    ownership: Ownership | null = null,
    /** The process's, shared by its hosts; a host on its own (tests, tools) writes its samples alone. */
    samples: SampleWriter = sampleWriter(db),
  ) {
    // Read and folded a page at a time: between pages, the event loop serves the other trials of this process.
    const history: StoredEvent[] = [];
    const state = fold(protocol, []);
    for await (const page of eventPages(db, trialId, { limit: OPENING_PAGE })) {
      for (const event of page) history.push(event);
      applyInPlace(state, page);
    }
    const host = new TrialHost(db, trialId, protocol, robot, history, state, log, ownership, samples);
    for (const [id, seqs] of await answeredRequests(db, trialId))
      host.requests.set(id, Promise.resolve({ ok: true, seqs }));
    // Looked for without a pair per action: a long trial's tens of thousands held the event loop for 6-10 ms.
    const interrupted: string[] = [];
    for (const actionId in host.state.actions) {
      const { status } = host.state.actions[actionId]!;
      if (status === "requested" || status === "running") interrupted.push(actionId);
    }
    // Each may have reached the robot before the process ended (most had, after a kill -9): not "failed".
    for (const actionId of interrupted) await host.command({ kind: "unknown", actionId, reason: RESTARTED }, null);
    // Timers running when the runtime stopped fire when they were due, from their logged start.
    host.limits.follow(host.state, host.t0);
    return host;
  }

  /**
   * The robot sensed one of its plugin's events: put through the same queue
   * and log as the wizard's commands, so the log orders a go on and an event
   * that come together, and the first ends the wait. Logged with the robot's
   * own time (`at`); when nothing waits for it, it is an observation only.
   */
  sensed(sensed: Sensed): Promise<CommandResult> {
    return this.command({ kind: "sensed", ...sensed }, null);
  }

  /** The robot's live state as the wizard sees it, and a listener for its changes. */
  get robotState(): LiveRobotState {
    return this.live;
  }

  onRobotState(listener: (state: LiveRobotState) => void) {
    this.liveListeners.add(listener);
  }

  guardStart(guard: (start: () => Promise<CommandResult>) => Promise<CommandResult>) {
    this.startGuard = guard;
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

  /** `moved`: this host closed, the client must follow the trial another way (the relay) from what it has. */
  subscribe(listener: (events: StoredEvent[]) => void, moved: () => void = () => {}) {
    this.listeners.set(listener, moved);
    return () => {
      if (this.listeners.delete(listener) && this.listeners.size === 0) this.lifecycle.unwatched();
    };
  }

  /** The robot's camera frames, for one watcher; apart from the commands and the log. */
  watchCamera(listener: (frame: CameraFrame) => void) {
    // Closed (the trial moved or ended): its robot link is closed too, and watching it would open nothing.
    if (this.shut) return () => {};
    this.cameraWatchers.add(listener);
    this.stopCamera ??= this.robot.watchCamera((frame) => {
      for (const watch of this.cameraWatchers) watch(frame);
    });
    return () => {
      if (this.cameraWatchers.delete(listener) && this.cameraWatchers.size === 0) {
        this.stopCamera?.();
        this.stopCamera = null;
      }
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
   * the robot is dropped (see `overtaken`), never sent after it. A request
   * seen before is answered with its first outcome.
   */
  command(command: Command, actorId: string | null, request?: Request): Promise<CommandResult> {
    if (request) {
      const first = this.requests.get(request.id);
      if (first) return first;
      // Asked again after a dropped connection, and never seen: too late to carry out now.
      if (request.retry) return Promise.resolve({ ok: false, reason: NEVER_ARRIVED });
      const answer = this.enqueue(command, actorId, request.id, request.askedAt);
      this.requests.set(request.id, answer);
      return answer;
    }
    return this.enqueue(command, actorId, null);
  }

  private enqueue(
    command: Command,
    actorId: string | null,
    requestId: string | null,
    moment?: number,
  ): Promise<CommandResult> {
    if (haltsTheRobot(command.kind)) {
      this.halts++;
      this.robot.halt();
    }
    const halts = this.halts;
    const asked = Date.now();
    // Too old already as this process reads it (it was itself frozen, or the page's message was held up).
    const stale = staleness(command.kind, moment ?? asked, asked);
    if (stale) return Promise.resolve({ ok: false, reason: this.dropped(command.kind, droppedReason(QUEUE, stale)) });
    // The log is stuck on an earlier command: refuse now rather than queue behind it.
    if (!ALWAYS_LOGGED.has(command.kind) && this.logStuck)
      return Promise.resolve({ ok: false, reason: LOG_UNAVAILABLE });
    const execute = () => this.execute(command, actorId, requestId, halts, asked, moment ?? asked);
    const run = this.queue.then(() => (command.kind === "start" ? this.startGuard(execute) : execute()));
    this.queue = run.catch(() => undefined);
    if (actorId !== null) {
      this.pace.backToBack = this.pace.waiting > 0 || asked - this.pace.answeredAt < BACK_TO_BACK_MS;
      this.pace.waiting++;
      const answered = () => {
        this.pace.waiting--;
        this.pace.answeredAt = Date.now();
      };
      void run.then(answered, answered);
    }
    return ALWAYS_LOGGED.has(command.kind) ? run : answeredBy(run, asked + LOG_DEADLINE_MS + DEADLINE_MARGIN_MS);
  }

  private async execute(
    command: Command,
    actorId: string | null,
    requestId: string | null,
    halts: number,
    asked: number,
    /** When the wizard asked: its freshness counts from then, not from when this process read it. */
    moment: number,
  ): Promise<CommandResult> {
    // A robot's late report, or a clock, after the host closed: the trial is no longer run from here.
    if (this.shut)
      return { ok: false, reason: this.fenced ? TAKEN_OVER : "This trial is no longer open here. Reload the page." };
    const before = this.overtaken(command, halts, asked);
    if (before) return { ok: false, reason: before === "stopped" ? NOT_CARRIED_OUT : LOG_UNAVAILABLE };
    const stale = staleness(command.kind, moment, Date.now());
    if (stale) return { ok: false, reason: this.dropped(command.kind, droppedReason(QUEUE, stale)) };
    // The robot's reports waiting go first, in this command's append; refused, it leaves them waiting.
    const waiting = this.reports ?? [];
    const { reports, decision } = decideAfterReports(this.protocol, this.state, waiting, command, this.eventNames);
    if (!decision.ok) return decision;
    if (waiting.length) this.takeReports();
    const written = await this.write(() => decision.events, actorId, requestId, reports);
    const halting = haltsTheRobot(command.kind);
    if (written === "fenced") return { ok: false, reason: TAKEN_OVER };
    if (written === "refused") return { ok: false, reason: halting ? STOP_NOT_LOGGED : LOG_UNAVAILABLE };
    if (written === "unknown") return { ok: false, reason: halting ? STOP_UNCONFIRMED : NOT_ANSWERED };
    if (written.earlier) {
      // An earlier command the wizard was told had not answered in time, landed late: taken in, never sent.
      this.take(written.events, NOT_SENT.late);
      // The robot's reports it carried are facts the log must hold: written on their own after it.
      if (waiting.length) await this.writeReports(waiting);
      // A report of the robot's, or a stop, is a fact the log must hold: written again after it.
      if (ALWAYS_LOGGED.has(command.kind)) return this.execute(command, actorId, requestId, halts, asked, moment);
      return { ok: false, reason: LOG_MOVED };
    }
    // Sent only while this process still holds the trial (`Ownership.owns`), asked in the same turn as the
    // send: a process that lost its lock, or was thawed after another took the trial, sends nothing. Only a
    // command requests actions (the robot's reports never do), so this is every send's one check; an
    // emergency stop is never asked (any process may stop a robot). The lock lost as this was logged, before
    // the new owner moved the epoch on (so the append went in): the wizard hears that now, not an ack.
    if (this.ownership && written.events.some(sentToRobot) && !(await this.ownership.owns())) {
      this.take(written.events, NOT_SENT.takenOver);
      return { ok: false, reason: TAKEN_OVER_AS_LOGGED };
    }
    // Stopped, or the log answered too late, while this was being logged: it is in the log as asked
    // for, and goes no further.
    const after = this.overtaken(command, halts, asked);
    const staleNow = after ? null : staleness(command.kind, moment, Date.now());
    this.take(
      written.events,
      after ? NOT_SENT[after] : staleNow && this.dropped(command.kind, droppedReason(QUEUE, staleNow)),
      moment,
    );
    return { ok: true, seqs: written.events.slice(reports.length).map((e) => e.seq) };
  }

  /**
   * What the robot's side reports (dispatched, completed, failed, timed out),
   * logged in turn like a command, never refused for lateness. While the
   * wizard's next command is likely in a moment (`nextCommandSoon`), reports
   * wait `REPORTS_WAIT_MS` for it, and its append carries them; else (and
   * then) they go in the queue for their own, which a command's still carries
   * if it comes first. Reports that come until their append is made up (the
   * group writer makes it up as its commit begins) are decided together and
   * written in that one append: an action's outcomes that happen together,
   * such as a completion right after the dispatch, cost one commit, not one
   * each.
   */
  private report(report: RobotReport) {
    // Reports after the host closed: the trial is no longer run from here.
    if (this.shut) return;
    if (report.kind === "dispatched" && report.detail?.playedBy === "browser") this.browserPlays.add(report.actionId);
    if (this.reports) {
      this.reports.push(report);
      return;
    }
    this.reports = [report];
    if (this.nextCommandSoon()) this.reportsDue = setTimeout(() => this.queueReports(), REPORTS_WAIT_MS);
    else this.queueReports();
  }

  /**
   * Whether the wizard's next command is likely in a moment: their commands come back to back, and the last
   * was answered within BACK_TO_BACK_MS (later, such a wizard would have sent the next). A report long after
   * (a line's end, seconds on) is logged at once, at the time it came.
   */
  private nextCommandSoon(): boolean {
    const { backToBack, waiting, answeredAt } = this.pace;
    return backToBack && (waiting > 0 || Date.now() - answeredAt < BACK_TO_BACK_MS);
  }

  /**
   * The reports waiting, into the queue for their own append, which they go in unless a command's carried
   * them first. Those that came while the host was open are written even as it closes, unless another
   * process has taken the trial: they happened while this one ran it.
   */
  private queueReports() {
    clearTimeout(this.reportsDue);
    const together = this.reports;
    if (!together) return;
    const run = this.queue.then(() => {
      if (this.reports === together && !this.fenced) return this.writeReports(together);
    });
    this.queue = run.catch(
      (error: unknown) => void logUnexpected(error, `logging the robot's reports of trial ${this.trialId}`),
    );
  }

  /** The reports waiting, taken by the append of the command that carries them. */
  private takeReports() {
    clearTimeout(this.reportsDue);
    this.reports = null;
  }

  private async writeReports(together: RobotReport[]): Promise<void> {
    const seal = () => {
      if (this.reports === together) this.reports = null;
    };
    const written = await this.write(
      () => {
        seal();
        return decideReports(this.protocol, this.state, together);
      },
      null,
      null,
    );
    // The log is away: like any command refused, the reports are not in it (an action left running is
    // marked failed when the trial is opened again).
    if (written === "refused" || written === "unknown" || written === "fenced") return;
    if (written.earlier) {
      this.take(written.events, NOT_SENT.late);
      return this.writeReports(together);
    }
    if (written.events.length) this.take(written.events, null);
  }

  /**
   * The log after `lastSeq` as this host opened it, with all it appended since, once: the hello that
   * opened the trial reads the log once, not twice. Null once taken (read the log then).
   */
  takeOpeningLog(lastSeq: number): StoredEvent[] | null {
    const log = this.opening;
    this.opening = null;
    // Whole, as a first hello asks for it, without a copy: a long trial's held the event loop for 6 ms.
    if (!log || (log[0]?.seq ?? Infinity) > lastSeq) return log;
    return log.filter((e) => e.seq > lastSeq);
  }

  /** A command dropped for its age: in the runtime's own log too, with how old and where. */
  private dropped(kind: Command["kind"], reason: string): string {
    console.warn(`[runtime] trial ${this.trialId}: dropped ${kind}: ${reason}`);
    return reason;
  }

  /**
   * Committed events: into the state, to the robot unless `withheld` says why not, then to every client;
   * `moment`, when the wizard asked for them (the robot link drops what is too old by then). The robot
   * first: a trial's many observers' sends never hold up what the robot is told.
   */
  private take(stored: StoredEvent[], withheld: string | null, moment: number | null = null) {
    this.opening?.push(...stored);
    applyInPlace(this.state, stored);
    this.t0 ??= startedAt(stored);
    if (withheld) this.withhold(stored, withheld);
    else this.carryOut(stored, moment);
    // Armed from their logged start, so arming after the robot is told changes no due time. None once the
    // host has closed (the reports it had, written as it closed, may start a question's clock).
    if (!this.shut) this.limits.follow(this.state, this.t0);
    for (const listener of this.listeners.keys()) listener(stored);
    if (this.state.status === "completed" || this.state.status === "aborted") this.lifecycle.ended();
  }

  /**
   * Appends what `decideEvents` gives as the writer makes the append up
   * (after the trial's cursor as it stands then), and when the append fails,
   * finds out what the log holds: a commit whose reply was lost is still a
   * commit. Only this host writes the trial (it holds the lock), so events past its cursor are its own: this
   * command's (taken as its outcome, never written twice), or an earlier
   * command's that landed late (`earlier`). "refused" when the statement
   * never reached the database; "unknown" when the log cannot be read either:
   * a later append meets whatever landed. "fenced" when another process has
   * taken the trial since this host did: what is past the cursor is its, and
   * this host writes nothing and sends the robot nothing again.
   */
  private async write(
    decideEvents: () => EngineEvent[],
    actorId: string | null,
    requestId: string | null,
    /** The robot's reports a command carries: before its events, by no one. */
    reports: EngineEvent[] = [],
  ): Promise<{ events: StoredEvent[]; earlier: boolean } | "refused" | "unknown" | "fenced"> {
    let cursor: TrialCursor | null = null;
    let events: EngineEvent[] = [];
    const append = () => {
      cursor = {
        id: this.trialId,
        lastSeq: this.state.lastSeq,
        t0: this.t0 === null ? null : new Date(this.t0),
        ...(this.ownership ? { epoch: this.ownership.epoch } : {}),
      };
      events = decideEvents();
      return { cursor, events, actorId, requestId, reports };
    };
    const unwatch = this.watchWrite();
    try {
      return { events: await this.log.append(append), earlier: false };
    } catch (error) {
      if (fencedOut(error)) {
        this.fenced = true;
        this.shut = true;
        this.ownership?.lost();
        return "fenced";
      }
      // Never made up (no cursor): the writer sent nothing of it.
      if (neverReachedDatabase(error) || cursor === null) return "refused";
      const after = (cursor as TrialCursor).lastSeq;
      const landed = await eventsSince(this.db, this.trialId, after).catch(() => null);
      if (landed === null) return "unknown";
      if (landed.length === 0) throw error;
      return { events: landed, earlier: !areTheseEvents(landed, [...reports, ...events]) };
    } finally {
      unwatch();
    }
  }

  /**
   * Marks the log stuck once a write has taken the log's deadline, counted while this process ran: a timer
   * that fires late (the process itself was frozen) starts the count again from its waking, so the write
   * that was under way as the process froze is given its answer before the log is called stuck.
   */
  private watchWrite(): () => void {
    let timer: ReturnType<typeof setTimeout>;
    const arm = () => {
      const due = Date.now() + LOG_DEADLINE_MS;
      timer = setTimeout(() => {
        if (Date.now() - due > STALL_SLACK_MS) arm();
        else this.logStuck = true;
      }, LOG_DEADLINE_MS);
    };
    arm();
    return () => {
      clearTimeout(timer);
      this.logStuck = false;
    };
  }

  /** Whether a command was overtaken since it was asked for: by a stop, or by the log's deadline. */
  private overtaken(command: Command, halts: number, asked: number): "stopped" | "late" | null {
    if (halts !== this.halts && MOVES_THE_ROBOT.has(command.kind)) return "stopped";
    if (!ALWAYS_LOGGED.has(command.kind) && Date.now() - asked > LOG_DEADLINE_MS) return "late";
    return null;
  }

  /** Each action held back is logged as not sent, with why: the log says it never reached the robot. */
  private withhold(events: EngineEvent[], reason: string) {
    for (const event of events)
      if (event.type === "action.requested")
        void this.command({ kind: "not_sent", actionId: event.actionId, reason }, null);
  }

  /** What happens in the world once the events are committed. */
  private carryOut(events: EngineEvent[], moment: number | null) {
    for (const event of events) {
      if (event.type !== "action.requested") continue;
      const report = (r: RobotReport) => this.report(r);
      if (sentToRobot(event)) {
        this.robot.perform(
          {
            actionId: event.actionId,
            actionType: event.actionType,
            parameters: event.parameters,
            ...(moment === null ? {} : { askedAt: moment }),
          },
          report,
        );
      } else if (event.actionType === "pause") {
        // The clock starts once "dispatched" is stored, so the logged hold is never shorter than designed.
        const seconds = Number(event.parameters.seconds ?? 0);
        void this.command({ kind: "dispatched", actionId: event.actionId }, null).then(() => {
          const timer = setTimeout(() => {
            this.timers.delete(timer);
            report({ kind: "completed", actionId: event.actionId, detail: { heldMs: seconds * 1000 } });
          }, seconds * 1000);
          this.timers.add(timer);
        });
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
    this.queueReports();
    this.shut = true;
    // Its clients still follow the trial, from whichever process runs it now.
    const moved = [...this.listeners.values()];
    this.listeners.clear();
    for (const move of moved) move();
    for (const t of this.timers) clearTimeout(t);
    this.limits.close();
    this.stopWatching();
    this.stopSensing();
    this.stopCamera?.();
    this.stopCamera = null;
    this.cameraWatchers.clear();
    await this.queue;
    await this.samples.close();
    this.robot.close();
  }
}
