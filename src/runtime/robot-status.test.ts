// A trial's robot status said to the other runtime processes: each change
// through PostgreSQL while the relay is open, nothing once it has closed (as
// the process stops, a link's late close would go to a closed database).
import type postgres from "postgres";
import { describe, expect, it } from "vitest";
import { robotStatusRelay } from "./robot-status";

describe("the robot status relay", () => {
  it("announces each change until it is closed, then none", async () => {
    const sent: string[] = [];
    const sql = {
      listen: async () => ({ unlisten: async () => {} }),
      notify: async (_channel: string, payload: string) => void sent.push(payload),
    } as unknown as postgres.Sql;
    const relay = await robotStatusRelay(sql, () => {});
    relay.announce("trial-1", { connected: true });
    await relay.close();
    relay.announce("trial-1", { connected: false, detail: "closed" });
    expect(sent.map((p) => JSON.parse(p))).toEqual([{ trialId: "trial-1", connected: true }]);
  });
});
