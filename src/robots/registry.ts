// The robot registry in the database: seeding it from the environment and the
// launcher, the robot a trial drives (chosen once, among those available to its
// study), who holds a robot now, and the live health the runtime writes.
// The rules themselves are pure (src/core/robots/registry.ts).
import { and, asc, eq, inArray, isNull, ne, or } from "drizzle-orm";
import { robotPreference, robotTaken, runsPlugin } from "@/core/robots/registry";
import { parseSecretReference, type SecretReference } from "@/core/robots/secrets";
import type { Database } from "@/store/client";
import { experiments, participants, robotStudies, robots, trials } from "@/store/schema";
import type { TransportConfig } from "./transports";
import { LIVE_STATUSES } from "@/core/trial/types";

export type RobotRecord = typeof robots.$inferSelect;

/**
 * Where the robot's SSH secret is read (null: it has none), or why the record cannot be used: one saved
 * before robot secrets had their own variables may name any (`parseSecretReference`).
 */
export function secretOf(robot: RobotRecord): SecretReference | null | { error: string } {
  if (!robot.sshSecret) return null;
  const secret = parseSecretReference(robot.sshSecret);
  return "error" in secret ? { error: `The SSH secret of "${robot.name}" ${secret.error}.` } : secret;
}

/** The ways to reach a registered robot, its SSH secret read from where the record says. */
export function connectionOf(
  robot: RobotRecord,
  env: NodeJS.ProcessEnv = process.env,
): { ok: true; config: TransportConfig } | { ok: false; reason: string } {
  let password: string | undefined;
  let privateKeyFile: string | undefined;
  const secret = secretOf(robot);
  if (secret) {
    if ("error" in secret) return { ok: false, reason: secret.error };
    if (secret.kind === "env") {
      password = env[secret.name];
      if (!password)
        return {
          ok: false,
          reason: `The SSH password of "${robot.name}" is read from the environment variable ${secret.name}, which is not set for the trial runtime.`,
        };
    } else privateKeyFile = secret.path;
  }
  const url = robot.rosbridgeUrl ?? undefined;
  return {
    ok: true,
    config: {
      rosbridgeUrl: url,
      // A plugin whose transport is "simulated" speaks rosbridge to the robot it is given, as it did
      // to HRI_ROSBRIDGE_URL before records: only robots registered for it, or for any plugin, get it.
      simulatorUrl: url,
      httpBaseUrl: robot.httpUrl ?? undefined,
      ssh:
        robot.sshHost && robot.sshUser
          ? { host: robot.sshHost, port: robot.sshPort, username: robot.sshUser, password, privateKeyFile }
          : undefined,
    },
  };
}

/** The robots a study may use, seeded and simulated ones included, by name. */
export function robotsOfStudy(db: Database, studyId: string) {
  return db
    .select()
    .from(robots)
    .where(
      or(
        eq(robots.allStudies, true),
        inArray(
          robots.id,
          db.select({ id: robotStudies.robotId }).from(robotStudies).where(eq(robotStudies.studyId, studyId)),
        ),
      ),
    )
    .orderBy(asc(robots.name));
}

/**
 * The robot the trial drives: the one it was given, or else (chosen now and
 * kept) a robot available to its study that runs its plugin, free ones first
 * (`robotPreference`): the first free one that `claim` takes, so runtimes
 * choosing at the same moment each take another; when none can be claimed,
 * the first of them (its start is refused until it is free). `claim` is also
 * asked for the robot given before.
 */
export async function robotOfTrial(
  db: Database,
  trialId: string,
  robotId: string,
  claim: (robot: RobotRecord) => Promise<boolean>,
): Promise<{ ok: true; robot: RobotRecord } | { ok: false; reason: string }> {
  const [trial] = await db
    .select({ studyId: trials.studyId, assigned: trials.assignedRobotId })
    .from(trials)
    .where(eq(trials.id, trialId));
  if (!trial) return { ok: false, reason: "This trial does not exist." };
  if (trial.assigned) {
    const [robot] = await db.select().from(robots).where(eq(robots.id, trial.assigned));
    if (robot) {
      await claim(robot);
      return { ok: true, robot };
    }
  }
  const available = await robotsOfStudy(db, trial.studyId);
  const live = await db
    .select({ robot: trials.assignedRobotId })
    .from(trials)
    .where(and(inArray(trials.status, [...LIVE_STATUSES]), ne(trials.id, trialId)));
  const held = new Set(live.map((l) => l.robot).filter((r) => r !== null));
  const preferred = robotPreference(available, robotId, held);
  if (!preferred.length)
    return {
      ok: false,
      reason: `No registered robot available to this study runs the ${robotId} plugin: an administrator registers one (Administration → Robots) and makes it available to the study.`,
    };
  let chosen = preferred[0]!;
  for (const robot of preferred.filter((r) => !held.has(r.id))) {
    if (!(await claim(robot))) continue;
    chosen = robot;
    break;
  }
  // Another opening of the same trial may have chosen first: the first choice stands.
  await db
    .update(trials)
    .set({ assignedRobotId: chosen.id })
    .where(and(eq(trials.id, trialId), isNull(trials.assignedRobotId)));
  const [kept] = await db
    .select()
    .from(robots)
    .innerJoin(trials, eq(trials.assignedRobotId, robots.id))
    .where(eq(trials.id, trialId));
  return { ok: true, robot: kept?.robots ?? chosen };
}

/**
 * The simulated robots a replay of the trial may use: those available to its study that run its plugin,
 * by name; and whether this server has a simulated robot at all (for the words of a refusal).
 */
export async function simulatedRobotsFor(
  db: Database,
  trialId: string,
  robotId: string,
): Promise<{ available: RobotRecord[]; any: boolean }> {
  const [trial] = await db.select({ studyId: trials.studyId }).from(trials).where(eq(trials.id, trialId));
  const [any] = await db.select({ id: robots.id }).from(robots).where(eq(robots.simulated, true)).limit(1);
  const ofStudy = trial ? await robotsOfStudy(db, trial.studyId) : [];
  return { available: ofStudy.filter((r) => r.simulated && r.rosbridgeUrl && runsPlugin(r, robotId)), any: !!any };
}

/** Whether a live trial (in progress or paused, of any study and any process) drives the robot. */
export async function drivenByLiveTrial(db: Database, robotId: string): Promise<boolean> {
  const [live] = await db
    .select({ id: trials.id })
    .from(trials)
    .where(and(eq(trials.assignedRobotId, robotId), inArray(trials.status, [...LIVE_STATUSES])))
    .limit(1);
  return !!live;
}

/**
 * The refusal when another live trial drives the robot, naming that trial in
 * the wizard's words: in full when it is of the same study, and only as "a
 * trial of another study" otherwise (a study's trials are its own business).
 */
export async function robotHeldBy(db: Database, robot: RobotRecord, trialId: string): Promise<string | null> {
  const [self] = await db.select({ studyId: trials.studyId }).from(trials).where(eq(trials.id, trialId));
  const [holder] = await db
    .select({
      id: trials.id,
      studyId: trials.studyId,
      experiment: experiments.name,
      participant: participants.code,
      status: trials.status,
    })
    .from(trials)
    .innerJoin(experiments, eq(experiments.id, trials.experimentId))
    .leftJoin(participants, eq(participants.id, trials.participantId))
    .where(
      and(eq(trials.assignedRobotId, robot.id), inArray(trials.status, [...LIVE_STATUSES]), ne(trials.id, trialId)),
    );
  if (!holder) return null;
  return robotTaken(robot.name, describeTrial(holder, holder.studyId === self?.studyId));
}

function describeTrial(
  t: { id: string; experiment: string; participant: string | null; status: string },
  sameStudy: boolean,
): string {
  if (!sameStudy) return "a trial of another study";
  const who = t.participant ? ` with participant ${t.participant}` : "";
  return `the trial of "${t.experiment}"${who}, ${t.status === "paused" ? "paused" : "in progress"}, id ${t.id.slice(0, 8)}`;
}

/** Whether an error is the database refusing a second live trial on one robot (the backstop across processes). */
export function isRobotTakenError(error: unknown): boolean {
  // Drizzle may wrap the driver's error: the constraint is on the error or its cause.
  for (
    let e = error as { code?: string; constraint_name?: string; cause?: unknown } | null;
    e;
    e = e.cause as typeof e
  ) {
    if (e.code === "23505" && e.constraint_name === "trials_live_robot_idx") return true;
  }
  return false;
}

/** The runtime's news of a robot: connected or not, its battery; "last seen" moves whenever it answers. */
export async function recordHealth(db: Database, robotId: string, health: { connected?: boolean; battery?: number }) {
  const seen = health.connected !== false ? { lastSeenAt: new Date() } : {};
  await db
    .update(robots)
    .set({ ...health, ...seen })
    .where(eq(robots.id, robotId));
}
