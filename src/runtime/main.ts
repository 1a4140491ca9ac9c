// The trial runtime process: `bun run src/runtime/main.ts`. The launcher
// starts it beside the web app with the same database and secret.
import { readConfig } from "@/store/config";
import { environmentSeed, seedRobots } from "@/store/robot-seeds";
import { createDatabase, createSessionClient } from "@/store/client";
import type { Plugin } from "@/core/plugins";
import { pluginCatalog } from "@/robots/catalog";
import { transportFor } from "@/robots/transports";
import { connectionOf, type RobotRecord } from "@/robots/registry";
import { ROBOT_STATE_TOPIC } from "@/core/robots/robot-state";
import type { LiveRobotState } from "@/core/robots/live-state";
import { pluginRobot, unavailableRobot } from "./robot-link";
import { purgeSpentTokens, watchAccess } from "./access";
import { eventRelay } from "./relay";
import { robotStatusRelay } from "./robot-status";
import { commandForwarding } from "./forwarding";
import { forwardedCommands } from "./carry-out";
import { stopLinks } from "./stop-links";
import { simulatorReplays } from "./replay";
import { startRuntimeServer } from "./server";
import { trialHosts, type RobotChoice } from "./trial-hosts";
import { robotHealth } from "./robot-health";

const config = readConfig();
if (!config.DATABASE_URL || !config.BETTER_AUTH_SECRET) {
  console.error("[runtime] DATABASE_URL and BETTER_AUTH_SECRET must be set (the launcher sets both).");
  process.exit(1);
}
const databaseUrl = config.DATABASE_URL;
const { db, sql, close } = createDatabase(databaseUrl);
for (const problem of (await pluginCatalog(db)).problems) console.error(`[runtime] plugin not loaded: ${problem}`);
// The robot the environment names (HRI_ROSBRIDGE_URL, HRI_ROBOT_SSH_*…) is a registered robot like any other.
const fromEnvironment = environmentSeed(config);
if (fromEnvironment) await seedRobots(db, [fromEnvironment]);
/** A plain link to a registered robot over the plugin's transport, or why it cannot be reached. */
const linkFor = (plugin: Plugin, robot: RobotRecord) => {
  const connection = connectionOf(robot);
  if (!connection.ok) return { link: unavailableRobot(connection.reason), transport: null };
  const choice = transportFor(plugin, connection.config);
  if (!choice.ok) return { link: unavailableRobot(choice.reason), transport: null };
  return { link: pluginRobot(plugin, choice.transport), transport: choice.transport };
};
// The plugin document is the trial's own (pinned by its version), and the robot the registered one
// it was given, both chosen in trialHosts; the robot's health goes to its record as it changes.
const health = robotHealth(db);
const robotFor = (plugin: Plugin | null, robotId: string, robot: RobotChoice) => {
  if (!plugin) return unavailableRobot(`no robot plugin "${robotId}" is installed`);
  if (!robot.ok) return unavailableRobot(robot.reason);
  const { link, transport } = linkFor(plugin, robot.robot);
  if (!transport) return link;
  // The simulated robot also reports what it is doing (speech, gesture, posture) on a topic of its own.
  const report = robot.robot.simulated
    ? (listener: (topic: string, message: unknown) => void) =>
        transport.subscribe(ROBOT_STATE_TOPIC, "std_msgs/msg/String", (m) => listener(ROBOT_STATE_TOPIC, m))
    : undefined;
  return health.withHealth(robot.robot.id, link, report);
};
let announceRobot: (trialId: string, connected: boolean, detail?: string) => void = () => {};
let announceRobotState: (trialId: string, state: LiveRobotState) => void = () => {};
const hosts = trialHosts(
  db,
  (closed) => createSessionClient(databaseUrl, closed),
  robotFor,
  (...args) => announceRobot(...args),
  config.HRI_TRIAL_IDLE_SECONDS * 1000,
  (...args) => announceRobotState(...args),
);
const relay = await eventRelay(db, sql);
// A trial another process runs: its wizards' stops go straight to the robot from here, and their
// commands to the owner through PostgreSQL.
const stops = stopLinks(db, (plugin, robot) => {
  const { link, transport } = linkFor(plugin, robot);
  return transport ? link : null;
});
const forwarding = await commandForwarding(sql, forwardedCommands(db, hosts));
// Replays go to simulated robots only, taken as trials take theirs: never one a trial or replay holds.
const replays = simulatorReplays(db, hosts.claims);
const runtime = startRuntimeServer({
  db,
  hosts,
  relay,
  replays,
  stops,
  forwarding,
  secret: config.BETTER_AUTH_SECRET,
  hostname: config.HOST,
  port: config.HRI_RUNTIME_PORT,
  iceServers: config.HRI_ICE_SERVERS,
  trustedProxies: config.HRI_TRUSTED_PROXIES,
});
// Robot status to this process's pages, and through PostgreSQL to those on every other runtime.
const robotStatus = await robotStatusRelay(
  sql,
  (trialId, { connected, detail }) =>
    void hosts.owned(trialId).then((host) => host || runtime.announceRobot(trialId, connected, detail)),
);
announceRobot = (trialId, connected, detail) => {
  runtime.announceRobot(trialId, connected, detail);
  robotStatus.announce(trialId, { connected, ...(detail ? { detail } : {}) });
};
announceRobotState = runtime.announceRobotState;
// Membership, role, blinding and assigned-wizard changes reach open sockets at once.
const access = await watchAccess(sql, runtime.accessChanged, runtime.recheckAll);
const purge = setInterval(
  () =>
    void purgeSpentTokens(db).catch((e: unknown) => console.error(`[runtime] used tokens not purged: ${String(e)}`)),
  3_600_000,
);
const server = runtime.server;
console.log(`[runtime] listening on ws://${server.hostname}:${server.port}`);

// A command stuck on a database that does not answer must not keep the process alive: shutdown is bounded.
const SHUTDOWN_MS = 4000;
const stop = async () => {
  setTimeout(() => {
    console.error(`[runtime] still shutting down after ${SHUTDOWN_MS / 1000} s: exiting now.`);
    process.exit(1);
  }, SHUTDOWN_MS).unref();
  clearInterval(purge);
  server.stop(true);
  await replays.close();
  stops.closeAll();
  await hosts.closeAll();
  // Ending the pool ends the listening connection too; unlistening first is a courtesy that a database
  // already gone (stopped, or crashed) answers with an error worth nothing at this point.
  await Promise.allSettled([relay.close(), forwarding.close(), access.close(), robotStatus.close(), health.settled()]);
  await close();
  process.exit(0);
};
process.on("SIGINT", () => void stop());
process.on("SIGTERM", () => void stop());
