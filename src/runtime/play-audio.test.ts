// "Play audio" through the real runtime path: on the simulated robot, whose
// plugin maps play_audio, the simulator receives the play command (the
// file's length, hash and name) over rosbridge and plays it for its length;
// on NAO6, whose plugin cannot play a file, the action waits for the wizard's
// browser, and only the browser's report of that very sound ends it.
import { readFileSync } from "node:fs";
import { afterAll, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "@/core/plugins";
import type { TrialProtocol } from "@/core/trial";
import { simulatedRobot, startSimulator } from "@/robots/simulator";
import { RosbridgeTransport } from "@/robots/transports/rosbridge";
import { eventsSince } from "@/store/event-store";
import { bareTrial, freshDatabase } from "../../tests/support/db";
import { pluginRobot } from "./robot-link";
import { TrialHost } from "./trial-host";

const plugin = (file: string) => {
  const loaded = loadPlugin(file, readFileSync(`plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
  return loaded.value as Plugin;
};
const SHA = "c".repeat(64);
const protocol: TrialProtocol = {
  steps: [
    {
      id: "s1",
      name: "Chime",
      actions: [
        {
          id: "chime",
          type: "play_audio",
          parameters: { fileId: "f1", name: "chime one.wav", sha256: SHA, durationMs: 120 },
        },
        { id: "hi", type: "say", parameters: { text: "hi" } },
      ],
    },
  ],
};

describe("Play audio in a live trial", async () => {
  const { db, close } = await freshDatabase();
  const simulated = plugin("simulated.json");
  const sim = await startSimulator({ port: 0, nodes: simulatedRobot(simulated, { msPerChar: 0 }) });
  afterAll(async () => {
    await sim.close();
    await close();
  });

  const settle = (host: TrialHost, predicate: () => boolean) =>
    new Promise<void>((resolve) => {
      const check = () => predicate() && resolve();
      host.subscribe(check);
      check();
    });
  const open = async (robot: Plugin) =>
    TrialHost.open(db, await bareTrial(db), protocol, pluginRobot(robot, new RosbridgeTransport({ url: sim.url })));

  it("the simulated robot receives the play command and plays the sound for its length", async () => {
    const host = await open(simulated);
    await host.command({ kind: "start" }, null);
    await host.command({ kind: "next" }, null);
    await settle(host, () => sim.state.playing !== null);
    expect(sim.state.playing).toEqual({ name: "chime one.wav", durationMs: 120 });
    const sent = sim.received.filter((r) => r.message.op === "publish" && r.message.topic === "/audio");
    expect(sent.map((r) => r.message.msg)).toEqual([{ data: `120 ${SHA} chime one.wav` }]);
    await settle(host, () => host.current.actions.chime!.status === "done");
    const log = await eventsSince(db, host.trialId);
    expect(log.filter((e) => "actionId" in e && e.actionId === "chime").map((e) => e.type)).toEqual([
      "action.requested",
      "action.dispatched",
      "action.completed",
    ]);
    expect(log.find((e) => e.type === "action.dispatched")).toMatchObject({ detail: { robotAction: "play_audio" } });
    // The browser has no say over a sound the robot played.
    expect(await host.browserPlayed("chime", undefined, null)).toEqual({
      ok: false,
      reason: "No sound of this trial is waiting for the browser to play it.",
    });
    await host.close();
  });

  it("on NAO6 the sound waits for the wizard's browser, whose report ends it once", async () => {
    const host = await open(plugin("nao6-ros2.json"));
    const before = sim.received.length;
    await host.command({ kind: "start" }, null);
    await host.command({ kind: "next" }, null);
    await settle(host, () => host.current.actions.chime!.status === "running");
    expect(sim.received.slice(before).some((r) => r.message.topic === "/audio")).toBe(false);
    const log = await eventsSince(db, host.trialId);
    expect(log.at(-1)).toMatchObject({ type: "action.dispatched", actionId: "chime", detail: { playedBy: "browser" } });
    // Not a robot action: "hi" was never handed to the browser.
    expect((await host.browserPlayed("hi", undefined, null)).ok).toBe(false);
    const played = await host.browserPlayed("chime", undefined, null);
    expect(played.ok).toBe(true);
    expect((await eventsSince(db, host.trialId)).at(-1)).toMatchObject({
      type: "action.completed",
      detail: { playedBy: "browser" },
    });
    expect(host.current.actions.chime!.status).toBe("done");
    expect((await host.browserPlayed("chime", undefined, null)).ok).toBe(false);
    await host.close();
  });

  it("a browser that cannot play the sound fails the action with its reason", async () => {
    const host = await open(plugin("nao6-ros2.json"));
    await host.command({ kind: "start" }, null);
    await host.command({ kind: "next" }, null);
    await settle(host, () => host.current.actions.chime!.status === "running");
    const failed = await host.browserPlayed("chime", "the file could not be fetched (HTTP 404)", null);
    expect(failed.ok).toBe(true);
    expect((await eventsSince(db, host.trialId)).at(-1)).toMatchObject({
      type: "action.failed",
      reason: "The wizard's browser could not play the sound: the file could not be fetched (HTTP 404)",
    });
    await host.close();
  });
});
