// The trial runtime process: `bun run src/runtime/main.ts`. The launcher
// starts it beside the web app with the same database and secret.
import { readConfig } from "@/server/config";
import { createDatabase } from "@/server/db/client";
import { timekeeperRobot } from "./robot";
import { startRuntimeServer } from "./server";
import { trialHosts } from "./trial-hosts";

const config = readConfig();
if (!config.DATABASE_URL || !config.BETTER_AUTH_SECRET) {
  console.error("[runtime] DATABASE_URL and BETTER_AUTH_SECRET must be set (the launcher sets both).");
  process.exit(1);
}
const { db, sql, close } = createDatabase(config.DATABASE_URL);
const lockConnection = await sql.reserve();
// Robot transports plug in here (see the robots issue); until then actions complete as sent.
const hosts = trialHosts(db, lockConnection, () => timekeeperRobot());
const server = startRuntimeServer({ db, hosts, secret: config.BETTER_AUTH_SECRET, hostname: config.HOST, port: config.HRI_RUNTIME_PORT });
console.log(`[runtime] listening on ws://${server.hostname}:${server.port}`);

const stop = async () => {
  server.stop(true);
  await hosts.closeAll();
  lockConnection.release();
  await close();
  process.exit(0);
};
process.on("SIGINT", () => void stop());
process.on("SIGTERM", () => void stop());
