// The transport contract under the faults a real bridge shows (issue 16): its
// process stopped with the socket open, and killed while an action is on its
// way. The simulated robot runs as its own process and is really stopped
// (SIGSTOP) and killed (SIGKILL). Within 2 s the link is declared lost, by
// construction: a ping goes out every 500 ms and one unanswered for 1500 ms
// gives the link up (the polls below allow a loaded machine more); no action
// sent into the dead link is ever reported completed: one that left before
// the loss was found is "sent, outcome unknown" (the bridge may read it once
// it goes on), one sent after it fails.
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import type { DispatchOutcome, Health } from "../../src/robots/transports/transport";
import { startSimulatorProcess, type SimulatorProcess } from "../support/simulator-process";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
const say = nao.actions.find((a) => a.id === "say_text")!;

let bridge: SimulatorProcess | null = null;
let transport: RosbridgeTransport | null = null;
afterEach(async () => {
  await transport?.close();
  bridge?.kill();
  transport = bridge = null;
});

async function connected() {
  bridge = await startSimulatorProcess();
  transport = new RosbridgeTransport({ url: bridge.url, backoffMs: { first: 100, max: 200 } });
  await transport.connect();
  const lost: Health[] = [];
  transport.onHealth((h) => h.state === "disconnected" && lost.push(h));
  // One action goes through first: the link works before the fault.
  expect(await transport.dispatch(say, { text: "before" })).toMatchObject({ status: "completed" });
  return { bridge, transport, lost };
}

const unknownWithReason = (outcome: DispatchOutcome) => {
  expect(outcome.status).toBe("unknown");
  expect((outcome as { reason: string }).reason).toMatch(/robot link was lost/);
};

const failedWithReason = (outcome: DispatchOutcome) => {
  expect(outcome.status).toBe("failed");
  expect((outcome as { reason: string }).reason).toMatch(/robot link was lost|not connected/);
};

describe("a bridge that stops answering (process stopped, socket open)", () => {
  it("is declared lost within 2 s, its socket torn down, and no action sent into it is completed", async () => {
    const { bridge, transport, lost } = await connected();
    bridge.freeze();
    const atOnce = transport.dispatch(say, { text: "sent as it froze" });
    await new Promise((r) => setTimeout(r, 600));
    const later = transport.dispatch(say, { text: "sent into the hang" });
    await expect.poll(() => lost.length, { timeout: 4000 }).toBe(1);
    expect(lost[0]!.reason).toMatch(/stopped answering/);
    unknownWithReason(await atOnce);
    unknownWithReason(await later);
    failedWithReason(await transport.dispatch({ ...say, retryable: false }, { text: "after the loss" }));
    // Torn down, not waiting on a close handshake the stopped bridge would never answer: once it goes on, a new link is made.
    bridge.thaw();
    await expect.poll(() => transport.health().state, { timeout: 10_000 }).toBe("connected");
    expect(await transport.dispatch(say, { text: "back" })).toMatchObject({ status: "completed" });
  });
});

describe("a bridge killed while an action is on its way", () => {
  it("reports the loss and the action's outcome unknown, never completed", async () => {
    const { bridge, transport, lost } = await connected();
    // Stopped first so the kill surely lands before the bridge could read the action.
    bridge.freeze();
    const sent = transport.dispatch(say, { text: "into the kill" });
    bridge.kill();
    await expect.poll(() => lost.length, { timeout: 4000 }).toBe(1);
    unknownWithReason(await sent);
  });
});
