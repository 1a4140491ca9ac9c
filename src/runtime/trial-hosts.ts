// The live trials this runtime process owns. A trial is owned by one process
// at a time: the first to take its PostgreSQL advisory lock. A host closes
// (robot link, its subscriptions, the lock) when its trial ends, and when no
// client has followed it for a while with nothing under way, so the robot
// connections held are bounded by the trials being run, not by every trial
// ever opened. A finished trial is opened without a robot at all.
//
// Each trial drives the registered robot it was given (src/robots/registry.ts),
// and one robot is never driven by two at once. A trial open here claims its
// robot (`robotClaims`, across processes) from the moment it is chosen until
// the trial closes here, so trials opened at once in several processes each
// take another robot; a start is refused while another open trial, a start or
// a replay holds the trial's robot, and while another live trial does (the
// database; its unique index is the last word when two processes start at the
// same moment).
//
// Taking a trial's lock also moves its epoch on (`takeTrial`): every append
// of the host carries the epoch it was opened with and is refused once
// another process has taken the trial since, so a process that lost its lock
// (its connection ended, the database restarted, the process frozen) writes
// nothing and, as it sends the robot only what it has just logged, commands
// the robot no more: its host closes and its clients follow the new owner.
// Each send also waits until the process knows it still holds the lock
// (the host asks `locks.owns`): a process thawed after a freeze asks before
// it sends.
import { eq } from "drizzle-orm";
import { checkingStart, eventNamesOf, type Plugin } from "@/core/plugins";
import { sliced } from "@/store/sliced";
import { conditionOfTrial } from "@/store/trial-condition";
import { inCondition } from "@/core/protocol/variants";
import type { Database } from "@/store/client";
import { experimentVersions, trials } from "@/store/schema";
import { trialPlugin } from "@/robots/trial-plugin";
import { isRobotTakenError, robotHeldBy, robotOfTrial, secretOf, type RobotRecord } from "@/robots/registry";
import { robotClaimed, robotTaken } from "@/core/robots/registry";
import { takeTrial } from "@/store/event-store";
import type { LiveRobotState } from "@/core/robots/live-state";
import type { RobotLink } from "./robot";
import { unavailableRobot } from "./robot-link";
import { type NewSession, trialLocks } from "./trial-locks";
import { robotClaims, type RobotClaims } from "./robot-claims";
import { logUnexpected } from "@/store/error-reference";
import { TrialHost, type CommandResult } from "./trial-host";
import { groupWriter } from "./log-writer";
import { sampleWriter } from "./samples";

export type RobotChoice = { ok: true; robot: RobotRecord } | { ok: false; reason: string };

const refused = (reason: string): CommandResult => ({ ok: false, reason });

/** A robot claim a trial holds while it is open here. */
type Held = { robotId: string; release: () => void };

export interface TrialHosts {
  /** The trial's host in this process, or null while another process owns the trial. */
  get(trialId: string): Promise<TrialHost | null>;
  /** The trial's host if this process runs it already; never opens it (a command forwarded to its owner). */
  owned(trialId: string): Promise<TrialHost | null>;
  closeAll(): Promise<void>;
  /** How many trials this process holds open now (with their robot links and locks). */
  readonly size: number;
  /** Who holds a robot while a trial starts on it or a replay plays on it; replays take theirs here too. */
  readonly claims: RobotClaims;
}

export function trialHosts(
  db: Database,
  /** Makes the trials' lock connection (`createSessionClient`), again whenever the one before died; closed with the hosts. */
  lockSession: NewSession,
  /**
   * The link to a trial's robot: `plugin` is the trial's plugin document (null when none is installed for
   * `robotId`), `robot` the registered robot it drives, or why it has none.
   */
  robotFor: (plugin: Plugin | null, robotId: string, robot: RobotChoice) => RobotLink | Promise<RobotLink>,
  onRobotStatus: (trialId: string, connected: boolean, detail?: string) => void,
  /** How long a trial nobody follows stays open, for a wizard who reloads or reconnects. */
  idleMs = 60_000,
  /** The robot's live state changed (what the wizard's page shows). */
  onRobotState: (trialId: string, state: LiveRobotState) => void = () => {},
): TrialHosts {
  const hosts = new Map<string, Promise<TrialHost | null>>();
  // Every trial of this process appends through one writer: one commit for what arrives together.
  const log = groupWriter(db);
  const samples = sampleWriter(db);
  /** The robot claim each trial open here holds (none when its robot was claimed elsewhere as it opened). */
  const claimOf = new Map<string, Held>();
  /** Robots whose trial is starting now (not yet live in the database), or that a replay plays on. */
  const claims = robotClaims(lockSession);
  // A lock lost with its connection and taken by another process: that process runs the trial now.
  const locks = trialLocks(lockSession, (trialId) => {
    void hosts
      .get(trialId)
      ?.then((host) => host && retire(trialId, host, false))
      .catch(retireFailed);
  });

  async function retire(trialId: string, host: TrialHost, unlock = true) {
    const current = hosts.get(trialId);
    if (!current || (await current.catch(() => null)) !== host) return;
    hosts.delete(trialId);
    await host.close();
    letGo(trialId);
    // Locks count: this releases exactly the hold this host took.
    if (unlock) await locks.release(trialId);
  }

  async function open(trialId: string) {
    if (!(await locks.take(trialId))) return null;
    try {
      const epoch = await takeTrial(db, trialId);
      if (epoch === null) throw new Error("This trial no longer exists.");
      return await hostFor(trialId, epoch);
    } catch (error) {
      // Refused, not owned: another attempt (or process) may take it once the cause is fixed.
      await locks.release(trialId);
      throw error;
    }
  }

  /** The trial's robot, claimed for this trial from the moment it is chosen (`robotOfTrial`). */
  async function chooseRobot(trialId: string, robotId: string) {
    let taken: Held | null = null;
    const made = await robotOfTrial(db, trialId, robotId, async (robot) => {
      // Lost with its session to another process: that one may drive the robot now, this one must not.
      const claim = await claims.take(robot.id, "open trial", () => robotLost(trialId, robot.name));
      if (claim.ok) taken = { robotId: robot.id, release: claim.release };
      return claim.ok;
    });
    const held = taken as Held | null;
    if (held && made.ok && made.robot.id === held.robotId) claimOf.set(trialId, held);
    else held?.release();
    return made;
  }

  const letGo = (trialId: string) => {
    claimOf.get(trialId)?.release();
    claimOf.delete(trialId);
  };

  /** The open trial's robot claimed elsewhere: its host closes (its robot link with it), and the wizard is told. */
  function robotLost(trialId: string, name: string) {
    onRobotStatus(trialId, false, robotClaimed(name, "elsewhere"));
    void hosts
      .get(trialId)
      ?.then((host) => host && retire(trialId, host))
      .catch(retireFailed);
  }

  async function hostFor(trialId: string, epoch: number) {
    const [row] = await db
      .select({ snapshot: experimentVersions.snapshot, rehearsal: trials.rehearsalSnapshot, status: trials.status })
      .from(trials)
      .leftJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
      .where(eq(trials.id, trialId));
    const stored = row?.snapshot ?? row?.rehearsal;
    if (!stored) throw new Error("This trial has no protocol to run.");
    // A trial runs its condition's variants; a rehearsal's snapshot was frozen as the condition it chose, if any.
    const protocol = inCondition(stored, row?.snapshot ? await conditionOfTrial(db, trialId) : null);
    const chosen = await trialPlugin(db, trialId);
    if (!chosen.ok) throw new Error(chosen.reason);
    // A robot whose plugin lacks an action of the version would fail it mid-trial: refused before the first step.
    // (A rehearsal pilots a draft, whose checks only warn.)
    const missing =
      row?.snapshot && row.status === "scheduled" && chosen.plugin
        ? await sliced(checkingStart(protocol, chosen.plugin))
        : null;
    if (missing) throw new Error(missing);
    const ended = row?.status === "completed" || row?.status === "aborted";
    let robot: RobotLink;
    let registered: RobotRecord | null = null;
    if (ended) robot = unavailableRobot("the trial has ended");
    else {
      const choice = await chooseRobot(trialId, chosen.robotId);
      registered = choice.ok ? choice.robot : null;
      try {
        robot = await robotFor(chosen.plugin, chosen.robotId, choice);
      } catch (error) {
        letGo(trialId);
        throw error;
      }
    }
    let host: TrialHost;
    // Fenced out (another process took the trial since): closed here, the lock given back if held again.
    const ownership = {
      epoch,
      lost: () => void retire(trialId, host, true).catch(retireFailed),
      owns: () => locks.owns(trialId),
    };
    try {
      host = await TrialHost.open(db, trialId, protocol, robot, log, ownership, samples);
    } catch (error) {
      letGo(trialId);
      throw error;
    }
    host.eventNames = eventNamesOf(chosen.plugin);
    if (registered) {
      const own = registered;
      host.robotName = own.name;
      host.guardStart((start) => startOn(own, trialId, start));
    }
    host.onRobotStatus((connected, detail) => onRobotStatus(trialId, connected, detail));
    host.onRobotState((state) => onRobotState(trialId, state));
    // Unwatched for idleMs: closes, unless an action is still under way (then looks again later).
    const retireIfIdle = () => {
      const timer = setTimeout(() => {
        if (host.closed || host.watched) return; // a client that came back starts the clock again as it leaves
        if (host.busy) return retireIfIdle();
        void retire(trialId, host).catch(retireFailed);
      }, idleMs);
      timer.unref?.();
    };
    host.onLifecycle({ ended: () => void retire(trialId, host).catch(retireFailed), unwatched: retireIfIdle });
    // Opened by a command or a hello that may never subscribe: it must not stay open for ever either.
    retireIfIdle();
    return host;
  }

  /** Starts the trial unless its robot's record cannot be used, or another trial or a replay drives it. */
  async function startOn(robot: RobotRecord, trialId: string, start: () => Promise<CommandResult>) {
    // A record saved before robot secrets had their own variables may name the platform's: nothing is sent.
    const secret = secretOf(robot);
    if (secret && "error" in secret) return refused(secret.error);
    // Held since the trial opened here; else (claimed elsewhere then) claimed now, for the start only.
    const own = claimOf.get(trialId)?.robotId === robot.id;
    const claim = own ? { ok: true as const, release: () => {} } : await claims.take(robot.id, "starting trial");
    // A live trial holding it is named; it may hold the robot's claim too, while open in some runtime.
    if (!claim.ok) return refused((await robotHeldBy(db, robot, trialId)) ?? robotClaimed(robot.name, claim.holder));
    try {
      const held = await robotHeldBy(db, robot, trialId);
      if (held) return refused(held);
      return await start();
    } catch (error) {
      if (!isRobotTakenError(error)) throw error;
      return refused((await robotHeldBy(db, robot, trialId)) ?? robotTaken(robot.name, "another trial"));
    } finally {
      claim.release();
    }
  }

  return {
    get(trialId) {
      let host = hosts.get(trialId);
      if (!host) {
        host = open(trialId);
        hosts.set(trialId, host);
        // Not owned here (yet): ask again next time, the owner may have gone.
        host.then(
          (h) => h ?? hosts.delete(trialId),
          () => hosts.delete(trialId),
        );
      }
      return host;
    },
    owned: async (trialId) => (await hosts.get(trialId)?.catch(() => null)) ?? null,
    get size() {
      return hosts.size;
    },
    claims,
    async closeAll() {
      for (const host of hosts.values()) await (await host.catch(() => null))?.close();
      hosts.clear();
      claimOf.clear();
      await Promise.all([locks.close(), claims.close()]);
    },
  };
}

const retireFailed = (error: unknown) => logUnexpected(error, "closing a trial");
