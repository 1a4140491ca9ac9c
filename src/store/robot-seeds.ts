// The robots the registry is seeded with: the simulated robots the launcher
// starts, and the one robot the environment names (HRI_ROSBRIDGE_URL or
// HRI_ROBOT_HTTP_URL, with HRI_ROBOT_SSH_*), as a deployment had before records.
// Seeding again at every start updates the same records (a simulator's ports
// change each time), never adds a second one.
import { resolve } from "node:path";
import { and, like, notInArray } from "drizzle-orm";
import { ROBOT_SECRET_PREFIX } from "../core/robots/secrets";
import type { Database } from "./client";
import type { Config } from "./config";
import { robots } from "./schema";

export interface RobotSeed {
  seededFrom: string;
  name: string;
  /** Null: runs any plugin (a simulated robot; the environment's robot, as before records). */
  pluginRobotId: string | null;
  simulated: boolean;
  rosbridgeUrl: string | null;
  sshHost: string | null;
  sshPort: number;
  sshUser: string | null;
  sshSecret: string | null;
  httpUrl: string | null;
}

/**
 * Makes or updates the seeded records. A new one is available to every study
 * (what a single-robot deployment did before records); an administrator may
 * narrow it afterwards, and seeding again leaves that choice alone.
 */
export async function seedRobots(db: Database, seeds: RobotSeed[]) {
  for (const seed of seeds) {
    const { seededFrom: _, ...connection } = seed;
    await db
      .insert(robots)
      .values({ ...seed, allStudies: true })
      .onConflictDoUpdate({ target: robots.seededFrom, set: connection });
  }
}

/** The simulated robots of this start, and no others: those of an earlier start with more are removed. */
export async function seedSimulators(db: Database, seeds: RobotSeed[]) {
  await seedRobots(db, seeds);
  const current = seeds.map((s) => s.seededFrom);
  await db
    .delete(robots)
    .where(
      and(like(robots.seededFrom, "simulator:%"), current.length ? notInArray(robots.seededFrom, current) : undefined),
    );
}

/** The robot the environment names, if it names one. Its SSH secret stays in the environment: the record points at it. */
export function environmentSeed(config: Config): RobotSeed | null {
  // SSH alone names no robot: npm start has always ignored HRI_ROBOT_SSH_* without a rosbridge address.
  if (!config.HRI_ROSBRIDGE_URL && !config.HRI_ROBOT_HTTP_URL) return null;
  const secret = config.HRI_ROBOT_SSH_PASSWORD
    ? "env:HRI_ROBOT_SSH_PASSWORD"
    : config.HRI_ROBOT_SSH_KEY_FILE
      ? `file:${resolve(config.HRI_ROBOT_SSH_KEY_FILE)}`
      : null;
  return {
    seededFrom: "environment",
    name: "Robot from the environment",
    pluginRobotId: null,
    simulated: false,
    rosbridgeUrl: config.HRI_ROSBRIDGE_URL ?? null,
    sshHost: config.HRI_ROBOT_SSH_HOST ?? null,
    sshPort: config.HRI_ROBOT_SSH_PORT,
    sshUser: config.HRI_ROBOT_SSH_HOST ? config.HRI_ROBOT_SSH_USER : null,
    sshSecret: secret,
    httpUrl: config.HRI_ROBOT_HTTP_URL ?? null,
  };
}

/**
 * The environment variable the launcher puts simulated robot `n`'s SSH password in (fresh at every start),
 * among the robots' secrets: a record may name no other (src/core/robots/secrets.ts).
 */
export const simulatorPasswordVariable = (n: number) => `${ROBOT_SECRET_PREFIX}SIMULATED_ROBOT_${n}`;

export function simulatorSeed(n: number, rosbridgeUrl: string, sshPort: number): RobotSeed {
  return {
    seededFrom: `simulator:${n}`,
    name: `Simulated robot ${n}`,
    pluginRobotId: null,
    simulated: true,
    rosbridgeUrl,
    sshHost: "127.0.0.1",
    sshPort,
    sshUser: "nao",
    sshSecret: `env:${simulatorPasswordVariable(n)}`,
    httpUrl: null,
  };
}
