// Runs the simulated robot on its own: `node --import tsx src/robots/simulator/main.ts`
// or from the launcher. SIM_PORT (default 9090), SIM_HOST (default 127.0.0.1)
// and SIM_PLUGIN (default plugins/nao6-ros2.json) choose where and as what;
// SIM_SSH_PORT with SIM_SSH_PASSWORD (and SIM_SSH_USER, default nao) also
// opens its SSH side for the plugin's NAOqi commands; SIM_MS_PER_CHAR (default
// 60) is how long it takes to say each character.
import { readFile } from "node:fs/promises";
import { loadPlugin, formatPluginError } from "../../core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "./index";

export async function startDefaultSimulator(env: Record<string, string | undefined> = process.env): Promise<Simulator> {
  const file = env.SIM_PLUGIN ?? "plugins/nao6-ros2.json";
  const loaded = loadPlugin(file, await readFile(file, "utf8"));
  if (!loaded.ok) throw new Error(loaded.errors.map(formatPluginError).join("\n"));
  return startSimulator({
    host: env.SIM_HOST ?? "127.0.0.1",
    port: Number(env.SIM_PORT ?? 9090),
    nodes: simulatedRobot(loaded.value, env.SIM_MS_PER_CHAR ? { msPerChar: Number(env.SIM_MS_PER_CHAR) } : {}),
    ssh:
      env.SIM_SSH_PORT && env.SIM_SSH_PASSWORD
        ? { port: Number(env.SIM_SSH_PORT), username: env.SIM_SSH_USER ?? "nao", password: env.SIM_SSH_PASSWORD }
        : undefined,
  });
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const sim = await startDefaultSimulator();
  console.log(`simulated robot: rosbridge on ${sim.url}${sim.ssh ? `, SSH on port ${sim.ssh.port}` : ""}`);
  const stop = () => void sim.close().then(() => process.exit(0));
  process.on("SIGINT", stop).on("SIGTERM", stop);
}
