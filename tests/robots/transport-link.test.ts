// The plumbing every transport shares: parameter checks, the pause between
// tries, what an unreachable robot means for an action, and a status that
// stays closed once closed.
import { describe, expect, it } from "vitest";
import type { PluginAction } from "../../src/core/plugins";
import {
  backoffDelay,
  checkedParameters,
  LinkedTransport,
  RECONNECT_BACKOFF,
  unreached,
} from "../../src/robots/transports/link";
import type { Health } from "../../src/robots/transports/transport";

const say = {
  id: "say",
  name: "Say",
  parameterSchema: {
    type: "object",
    properties: { text: { type: "string" }, volume: { type: "number", default: 0.5 } },
    required: ["text"],
  },
} as unknown as PluginAction;

describe("shared transport plumbing", () => {
  it.each<[string, Record<string, unknown>, unknown]>([
    ["fills the schema's defaults in", { text: "Hi" }, { ok: true, parameters: { text: "Hi", volume: 0.5 } }],
    [
      "refuses what the schema refuses, naming the parameter",
      {},
      { ok: false, outcome: { status: "failed", reason: expect.stringContaining("text") } },
    ],
  ])("checked parameters: %s", (_, parameters, expected) => {
    expect(checkedParameters(say, parameters)).toEqual(expected);
  });

  it.each([
    [0, 250],
    [1, 500],
    [4, 4000],
    [5, 5000],
    [12, 5000],
  ])("reconnect try %i waits %i ms", (tries, ms) => {
    expect(backoffDelay(tries, RECONNECT_BACKOFF)).toBe(ms);
  });

  it("an unreached robot times a retryable action out and fails any other at once", () => {
    expect(unreached({ ...say, retryable: true }, Date.now(), "gone").status).toBe("timed_out");
    expect(unreached(say, Date.now(), "gone")).toEqual({ status: "failed", reason: "gone" });
  });

  it("tells each change of state once, and nothing after closed", async () => {
    class Probe extends LinkedTransport {
      connect = async () => this.setState("connected");
      dispatch = async () => ({ status: "completed" as const });
      close = async () => this.setState("closed");
      lose = () => this.setState("disconnected");
    }
    const transport = new Probe();
    const seen: Health["state"][] = [];
    transport.onHealth((h) => seen.push(h.state));
    await transport.connect();
    await transport.connect();
    await transport.close();
    transport.lose();
    expect(seen).toEqual(["connected", "closed"]);
    expect(transport.health().state).toBe("closed");
  });
});
