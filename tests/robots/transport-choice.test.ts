import { readFileSync } from "node:fs";
import { afterAll, describe, expect, it } from "vitest";
import { loadPlugin, unreachable, type Plugin } from "../../src/core/plugins";
import { startDefaultSimulator } from "../../src/robots/simulator/main";
import { channelsOf, transportFor } from "../../src/robots/transports";

const plugin = (file: string) => (loadPlugin(file, readFileSync(`plugins/${file}`, "utf8")) as { value: Plugin }).value;

describe("choosing a transport from the plugin", () => {
  const simulator = startDefaultSimulator({ SIM_PORT: "0" });
  afterAll(async () => (await simulator).close());

  it("the simulated plugin runs its abstract actions on the default simulated robot", async () => {
    const sim = await simulator;
    const simulated = plugin("simulated.json");
    const choice = transportFor(simulated, { simulatorUrl: sim.url });
    if (!choice.ok) throw new Error(choice.reason);
    await choice.transport.connect();
    const gesture = simulated.actions.find((a) => a.id === "gesture")!;
    expect(await choice.transport.dispatch(gesture, { name: "wave" })).toEqual({
      status: "completed",
      detail: { topic: "/gesture", confirmation: { by: "delivered", confirmed: false } },
    });
    await choice.transport.close();
  });

  it.each([
    [
      "turtlebot3-burger.json",
      {},
      "TurtleBot3 Burger cannot be reached: it needs the robot's rosbridge, and this server has no address for it: set HRI_ROSBRIDGE_URL (see docs/robot-setup.md)",
    ],
    [
      "simulated.json",
      {},
      "Simulated robot cannot be reached: it needs the simulated robot, which this server is not running (npm start runs it when HRI_ROSBRIDGE_URL is not set)",
    ],
  ])("%s with %j: %s", (file, config, reason) => {
    expect(transportFor(plugin(file), config)).toEqual({ ok: false, reason });
  });

  it("fails a NAOqi action at once when no SSH address is set, with the designer's reason", async () => {
    const sim = await simulator;
    const nao = plugin("nao6-ros2.json");
    const choice = transportFor(nao, { rosbridgeUrl: sim.url });
    if (!choice.ok) throw new Error(choice.reason);
    const sit = nao.actions.find((a) => a.id === "sit")!;
    const why = unreachable(nao, sit, channelsOf({ rosbridgeUrl: sim.url }));
    expect(why).toMatch(/^it needs SSH to the robot/);
    expect(await choice.transport.dispatch(sit, {})).toEqual({
      status: "failed",
      reason: `"Sit" cannot run on ${nao.name}: ${why}`,
    });
    await choice.transport.close();
  });
});
