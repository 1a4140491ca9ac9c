// The runtime's trial hosts on a simulated robot of one plugin, as the
// runtime opens them, for runtime tests that drive trials without sockets:
// the real roslib client against the simulator over a real socket, the robot
// saying each line at once.
import type { Plugin } from "../../src/core/plugins";
import { simulatedRobot, startSimulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { pluginRobot } from "../../src/runtime/robot-link";
import { trialHosts } from "../../src/runtime/trial-hosts";
import type { Database } from "../../src/store/client";
import { createSessionClient } from "../../src/store/client";

/** `idleMs`: how long a trial nobody follows stays open (the runtime's default when unset). */
export async function simulatedHosts(db: Database, url: string, plugin: Plugin, idleMs?: number) {
  const sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  const hosts = trialHosts(
    db,
    () => createSessionClient(url),
    () => pluginRobot(plugin, new RosbridgeTransport({ url: sim.url })),
    () => {},
    idleMs,
  );
  return {
    sim,
    hosts,
    async close() {
      await hosts.closeAll();
      await sim.close();
    },
  };
}
