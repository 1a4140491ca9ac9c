// Registered simulated robots for the runtime tests that drive several at once:
// each a robot record on a simulator of its own, available to the test's study.
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import type { Database } from "../../src/store/client";
import { robotStudies, robots } from "../../src/store/schema";
import { firstPartyPlugin } from "./plugins";

export interface RegisteredRobot {
  id: string;
  name: string;
  sim: Simulator;
}

/** A simulated robot that speaks at once (no time per character), so a test waits on nothing but the runtime. */
export const quickSimulator = () =>
  startSimulator({ port: 0, nodes: simulatedRobot(firstPartyPlugin("simulated.json"), { msPerChar: 0 }) });

/** One robot per name, on the simulator `simulator` gives its index (by default a quick one of its own), available to `studyId`. */
export async function registerRobots(
  db: Database,
  studyId: string,
  names: string[],
  simulator: (index: number) => Simulator | Promise<Simulator> = quickSimulator,
): Promise<RegisteredRobot[]> {
  const registered: RegisteredRobot[] = [];
  for (const [index, name] of names.entries()) {
    const sim = await simulator(index);
    const [row] = await db.insert(robots).values({ name, simulated: true, rosbridgeUrl: sim.url }).returning();
    await db.insert(robotStudies).values({ robotId: row!.id, studyId });
    registered.push({ id: row!.id, name, sim });
  }
  return registered;
}
