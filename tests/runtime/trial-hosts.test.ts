// Trials held open by the runtime close again: when they end, and when no
// client has followed them for a while. The robot connections and trial
// locks a runtime holds are bounded by the trials being run, with the real
// roslib client against the simulated robot and the real advisory locks.
import { sql } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { experiments, studies, trials } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { simulatedHosts } from "../support/simulated-hosts";

const plugin = firstPartyPlugin("simulated.json");

const protocol: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
  steps: [
    {
      id: "s1",
      name: "Greeting",
      description: "",
      actions: [{ id: "hi", type: "say", name: "", parameters: { text: "Hi" }, parallelGroup: null }],
    },
    {
      id: "s2",
      name: "Wait",
      description: "",
      actions: [{ id: "hold", type: "pause", name: "", parameters: { seconds: 3 }, parallelGroup: null }],
    },
  ],
};

const { db, url, close } = await freshDatabase();
const IDLE_MS = 200;
const { sim, hosts, close: closeHosts } = await simulatedHosts(db, url, plugin, IDLE_MS);

afterAll(async () => {
  await closeHosts();
  await close();
});

async function newTrials(count: number): Promise<string[]> {
  const [study] = await db.insert(studies).values({ title: "Hosts" }).returning();
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId: study!.id, name: "E", robotId: "simulated" })
    .returning();
  const rows = await db
    .insert(trials)
    .values(
      Array.from({ length: count }, () => ({
        studyId: study!.id,
        experimentId: experiment!.id,
        isRehearsal: true,
        rehearsalSnapshot: protocol,
      })),
    )
    .returning({ id: trials.id });
  return rows.map((r) => r.id);
}

/** Advisory locks held in this test's database: one per trial a runtime owns. */
async function trialLocks(): Promise<number> {
  const [row] = await db.execute<{ n: number }>(
    sql`select count(*)::int as n from pg_locks where locktype = 'advisory' and database = (select oid from pg_database where datname = current_database())`,
  );
  return row!.n;
}

async function until(check: () => boolean | Promise<boolean>, what: string) {
  for (let i = 0; i < 400; i++) {
    if (await check()) return;
    await new Promise((r) => setTimeout(r, 25));
  }
  throw new Error(`still waiting for ${what}`);
}

describe.sequential("the trials a runtime holds open", () => {
  it("closes each trial as it ends: 1,000 trials run leave no robot connection or lock behind", {
    timeout: 300_000,
  }, async () => {
    const ids = await newTrials(1000);
    let peak = 0;
    let robots = 0;
    // Ten wizards at a time, as a busy lab server might see.
    for (let i = 0; i < ids.length; i += 10) {
      await Promise.all(
        ids.slice(i, i + 10).map(async (trialId) => {
          const host = (await hosts.get(trialId))!;
          const spoken = new Promise<void>((resolve) =>
            host.subscribe((events) => events.some((e) => e.type === "action.completed") && resolve()),
          );
          expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
          expect((await host.command({ kind: "next" }, null)).ok).toBe(true);
          await spoken;
          expect((await host.command({ kind: "complete" }, null)).ok).toBe(true);
        }),
      );
      peak = Math.max(peak, hosts.size);
      robots = Math.max(robots, sim.connections());
    }
    // Every trial spoke through a connection of its own.
    const spokenBy = new Set(sim.received.filter((r) => r.message.op === "publish").map((r) => r.connection));
    expect(spokenBy.size).toBe(1000);
    expect(peak).toBeLessThanOrEqual(20);
    expect(robots).toBeLessThanOrEqual(20);
    await until(
      async () => hosts.size === 0 && sim.connections() === 0 && (await trialLocks()) === 0,
      "every trial to close",
    );
  });

  it("keeps a followed trial open, and closes it once nobody has followed it for a while", async () => {
    const [trialId] = await newTrials(1);
    const host = (await hosts.get(trialId!))!;
    const unsubscribe = host.subscribe(() => {});
    await host.command({ kind: "start" }, null);
    await until(() => sim.connections() === 1, "the robot connection");
    await new Promise((r) => setTimeout(r, IDLE_MS * 3));
    expect(hosts.size).toBe(1);
    expect(await trialLocks()).toBe(1);
    unsubscribe();
    await until(
      async () => hosts.size === 0 && sim.connections() === 0 && (await trialLocks()) === 0,
      "the idle trial to close",
    );
    // A wizard who comes back finds the trial where it was, in a host opened afresh.
    const again = (await hosts.get(trialId!))!;
    expect(again).not.toBe(host);
    expect(again.current.status).toBe("in_progress");
    expect(await host.command({ kind: "next" }, null)).toEqual({
      ok: false,
      reason: "This trial is no longer open here. Reload the page.",
    });
    expect((await again.command({ kind: "complete" }, null)).ok).toBe(true);
    await until(async () => hosts.size === 0 && (await trialLocks()) === 0, "the ended trial to close");
  });

  it("keeps an unfollowed trial open while an action is under way, and closes it after", async () => {
    const [trialId] = await newTrials(1);
    const host = (await hosts.get(trialId!))!;
    await host.command({ kind: "start" }, null);
    await host.command({ kind: "next" }, null);
    await until(() => host.current.actions.hi?.status === "done", "the greeting");
    await host.command({ kind: "next" }, null);
    await host.command({ kind: "next" }, null);
    await until(() => host.current.actions.hold?.status === "running", "the pause to start");
    await new Promise((r) => setTimeout(r, IDLE_MS * 3));
    expect(hosts.size).toBe(1);
    await until(() => hosts.size === 0 && sim.connections() === 0, "the trial to close once the pause is over");
    expect(host.current.actions.hold?.status).toBe("done");
  });

  it("takes its locks again on a new connection when the lock connection dies", async () => {
    const [kept, later] = await newTrials(2);
    const host = (await hosts.get(kept!))!;
    const unsubscribe = host.subscribe(() => {});
    expect(await trialLocks()).toBe(1);
    // An administrator (or a restart) ends the connection the locks live on.
    await db.execute(
      sql`select pg_terminate_backend(pid) from pg_locks where locktype = 'advisory' and database = (select oid from pg_database where datname = current_database())`,
    );
    await until(async () => (await trialLocks()) === 0, "the lock to go with its connection");
    const next = await hosts.get(later!);
    expect(next).not.toBeNull();
    expect(await trialLocks()).toBe(2);
    expect(await hosts.get(kept!)).toBe(host);
    unsubscribe();
    await next!.command({ kind: "start" }, null);
    await next!.command({ kind: "complete" }, null);
    await host.command({ kind: "start" }, null);
    await host.command({ kind: "complete" }, null);
    await until(async () => hosts.size === 0 && (await trialLocks()) === 0, "both trials to close");
  });

  it("opens a finished trial without connecting to its robot", async () => {
    const [trialId] = await newTrials(1);
    const host = (await hosts.get(trialId!))!;
    await host.command({ kind: "start" }, null);
    await host.command({ kind: "abort", reason: "the participant left" }, null);
    await until(() => hosts.size === 0 && sim.connections() === 0, "the aborted trial to close");
    const reopened = (await hosts.get(trialId!))!;
    expect(reopened.current.status).toBe("aborted");
    expect(reopened.robotStatus()).toBe(false);
    expect(sim.connections()).toBe(0);
    await until(async () => hosts.size === 0 && (await trialLocks()) === 0, "the unfollowed finished trial to close");
  });
});
