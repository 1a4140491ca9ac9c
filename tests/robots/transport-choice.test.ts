import { readFileSync } from "node:fs";
import { afterAll, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { startDefaultSimulator } from "../../src/robots/simulator/main";
import { transportFor } from "../../src/robots/transports";

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
      detail: { topic: "/gesture" },
    });
    await choice.transport.close();
  });

  it.each([
    ["turtlebot3-burger.json", {}, "no rosbridge address configured for turtlebot3-burger"],
    ["simulated.json", {}, "the simulated robot is not running"],
  ])("%s with %j: %s", (file, config, reason) => {
    expect(transportFor(plugin(file), config)).toEqual({ ok: false, reason });
  });
});
