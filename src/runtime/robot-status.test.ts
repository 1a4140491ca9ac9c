// A trial's robot status said to the other runtime processes: each change
// through PostgreSQL while the relay is open, nothing once it has closed (as
// the process stops, a link's late close would go to a closed database), and
// what was said before the close goes out before it returns.
import postgres from "postgres";
import { afterAll, describe, expect, it, vi } from "vitest";
import { freshDatabase } from "../../tests/support/db";
import { type RobotStatus, robotStatusRelay } from "./robot-status";

describe("the robot status relay", async () => {
  const { sql, url, close } = await freshDatabase();
  afterAll(close);

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

  it("announces a trial's changes in the order they happened, however fast they come (a link dropping and coming back)", async () => {
    const heard: Array<RobotStatus & { trialId: string }> = [];
    const listening = await robotStatusRelay(sql, (trialId, status) => heard.push({ trialId, ...status }));
    const announcing = await robotStatusRelay(sql, () => {});
    // Five trials, each with 100 changes said back to back (the pool has several connections to say them on).
    const said = Array.from({ length: 500 }, (_, i) => ({
      trialId: `trial-${i % 5}`,
      connected: i % 2 === 0,
      ...(i % 2 ? { detail: `lost ${i}` } : {}),
    }));
    for (const { trialId, ...status } of said) announcing.announce(trialId, status);
    for (let i = 0; i < 250 && heard.length < said.length; i++) await new Promise((r) => setTimeout(r, 20));
    expect(heard).toEqual(said);
    await Promise.all([listening.close(), announcing.close()]);
  });

  it("sends what was said before it closed, before the pool ends (a runtime stopping with its robots' links)", async () => {
    const heard: Array<RobotStatus & { trialId: string }> = [];
    const listening = await robotStatusRelay(sql, (trialId, status) => heard.push({ trialId, ...status }));
    const own = postgres(url, { max: 4, onnotice: () => {} });
    const logged = vi.spyOn(console, "error").mockImplementation(() => {});
    try {
      const stopping = await robotStatusRelay(own, () => {});
      // Fifty trials' links closing as the process stops, then the pool ended, as main.ts does.
      const said = Array.from({ length: 50 }, (_, i) => ({
        trialId: `trial-${i}`,
        connected: false,
        detail: "closed",
      }));
      for (const { trialId, ...status } of said) stopping.announce(trialId, status);
      await stopping.close();
      await own.end();
      for (let i = 0; i < 250 && heard.length < said.length; i++) await new Promise((r) => setTimeout(r, 20));
      expect(heard).toEqual(said);
      expect(logged).not.toHaveBeenCalled();
    } finally {
      logged.mockRestore();
      await listening.close();
    }
  });
});
