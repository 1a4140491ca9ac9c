// Commands forwarded to the process that runs their trial, over a real
// PostgreSQL: answered by the owner; and when the database does not take a
// request (a connection caught by a restart), the wizard is answered "no
// answer" in time, and the trial's later requests still go through.
import { afterAll, describe, expect, it } from "vitest";
import { freshDatabase } from "../../tests/support/db";
import { commandForwarding, type Forwarded } from "./forwarding";

describe("command forwarding", async () => {
  const { sql, close } = await freshDatabase();
  const served: string[] = [];
  const owner = await commandForwarding(sql, async (request) => {
    served.push(request.requestId);
    return { ok: true, seqs: [served.length] };
  });
  // The asking process's client: as the database's, except that while `stuck` its statements never answer.
  let stuck = false;
  const client = Object.assign((...args: Parameters<typeof sql>) => (stuck ? new Promise(() => {}) : sql(...args)), {
    listen: sql.listen.bind(sql),
  }) as unknown as typeof sql;
  const asker = await commandForwarding(client, async () => null);
  afterAll(async () => {
    await Promise.all([owner.close(), asker.close()]);
    await close();
  });
  const request = (requestId: string): Forwarded => ({
    trialId: "t1",
    userId: "u1",
    requestId,
    command: { kind: "next" },
  });

  it("gives the owner's answer", async () => {
    expect(await asker.forward(request("r1"))).toEqual({ ok: true, seqs: [1] });
    expect(served).toEqual(["r1"]);
  });

  it("answers 'no answer' when the request is not taken in time, and the trial's next requests go on", {
    timeout: 30_000,
  }, async () => {
    stuck = true;
    const waiting = [asker.forward(request("r2")), asker.forward(request("r3"))];
    expect(await Promise.all(waiting)).toEqual([null, null]);
    stuck = false;
    expect(await asker.forward(request("r4"))).toEqual({ ok: true, seqs: [2] });
    expect(served).toEqual(["r1", "r4"]);
  });
});
