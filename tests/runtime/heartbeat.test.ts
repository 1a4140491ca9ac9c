// The trial socket's heartbeat against a real runtime process. A frozen
// runtime (SIGSTOP) keeps its sockets open, so only the heartbeat tells a
// page it stopped: the page's own heartbeat logic sees it silent while it is
// still frozen, and live again on the same connection once it resumes, with
// nothing lost; the runtime, frozen longer than it waits for a silent page,
// does not drop its pages for its own silence, but does drop a page that
// stopped pinging, and keeps one that pings only when asked (a hidden tab).
import type { ChildProcess } from "node:child_process";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { PAGE_GONE_AFTER_MS, type RuntimeLink } from "../../src/core/socket/heartbeat";
import { startHeartbeat } from "../../src/features/execution/heartbeat";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { trialOf } from "../support/trial-rows";

const SECRET = "heartbeat-test-secret".padEnd(40, "x");

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 2 });
let runtime: { url: string; child: ChildProcess };
let wizardId = "";
let trialId = "";
let frozen = false;

beforeAll(async () => {
  runtime = await startRuntime(url, SECRET);
  const [study] = await db.insert(studies).values({ title: "Heartbeat", status: "active" }).returning();
  const wizard = await createAccount(db, {
    name: "Wizard",
    email: "heartbeat@example.org",
    password: "password-123",
    role: "researcher",
  });
  wizardId = wizard.id;
  await db.insert(studyMembers).values({ studyId: study!.id, userId: wizard.id, role: "wizard" });
  const snapshot: ProtocolSnapshot = {
    schemaVersion: 5,
    experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
    steps: [{ id: "s1", name: "One", description: "", actions: [] }],
  };
  trialId = await trialOf(db, { studyId: study!.id, wizardId: wizard.id, snapshot });
}, 120_000);

afterAll(async () => {
  if (frozen) process.kill(runtime.child.pid!, "SIGCONT");
  runtime?.child.kill("SIGKILL");
  await close();
});

const open = () => connectTrial(runtime.url, signSocketToken({ userId: wizardId, trialId }, SECRET));
const seqsOf = (socket: TrialSocket) =>
  socket.messages.flatMap((m) => ((m.events as Array<{ seq: number }> | undefined) ?? []).map((e) => e.seq));

/** Resolves once `ready()` holds, checking every 50 ms; fails after `ms`. */
async function until(ready: () => boolean, what: string, ms = 20_000) {
  for (let waited = 0; !ready(); waited += 50) {
    if (waited > ms) throw new Error(`Never happened: ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

describe("the trial socket's heartbeat", () => {
  it("shows a frozen runtime silent while it is frozen, and live again with nothing lost once it resumes", {
    timeout: 90_000,
  }, async () => {
    const page = await open();
    // What the page shows of the runtime, in order, and whether the runtime was frozen when each was shown.
    const shown: Array<{ link: RuntimeLink; whileFrozen: boolean }> = [];
    const heartbeat = startHeartbeat(page.send, (link) => shown.push({ link, whileFrozen: frozen }));
    page.listen((m) => heartbeat.heard(m));
    expect((await page.command("before", { kind: "note", text: "Before the freeze" })).type).toBe("ack");
    await page.next((m) => m.type === "pong");

    process.kill(runtime.child.pid!, "SIGSTOP");
    frozen = true;
    // Sent as the runtime froze, before the page could know: waits in the socket, is carried out on resume.
    page.send({ type: "command", requestId: "during", command: { kind: "note", text: "As the runtime froze" } });
    await until(() => shown.some((s) => s.link === "silent"), "the page saw the runtime silent");
    expect(shown).toEqual([{ link: "silent", whileFrozen: true }]);
    // Frozen for longer than the runtime waits for a silent page: on waking, its pages' pings are unread, not missing.
    await new Promise((r) => setTimeout(r, PAGE_GONE_AFTER_MS + 1000));
    expect(shown.at(-1)!.link).toBe("silent");

    frozen = false;
    process.kill(runtime.child.pid!, "SIGCONT");
    await until(() => shown.at(-1)!.link === "live", "the page saw the runtime live again");
    expect(shown.map((s) => s.link)).toEqual(["silent", "live"]);
    expect(await page.next((m) => m.requestId === "during" && m.type !== "halted")).toMatchObject({ type: "ack" });
    expect((await page.command("after", { kind: "note", text: "After the freeze" })).type).toBe("ack");
    // The same connection throughout, every event once and in order.
    expect(page.closed).toBeNull();
    const seqs = seqsOf(page);
    expect(seqs).toEqual(Array.from({ length: seqs.length }, (_, i) => i + 1));
    // Still answering a while later: the runtime kept the page.
    await new Promise((r) => setTimeout(r, 1500));
    expect(page.closed).toBeNull();
    expect(shown.at(-1)!.link).toBe("live");
    heartbeat.stop();
    page.close();
  });

  it("keeps a page that answers when asked (a hidden tab), and drops one that stopped, in plain words", {
    timeout: 60_000,
  }, async () => {
    const gone = await open();
    const hidden = await open();
    // Both pinged once. One then went silent (frozen, or its computer asleep); the other's timers are held back
    // (a hidden tab): it pings only when the runtime asks, from its message handler.
    for (const page of [gone, hidden]) {
      page.send({ type: "ping", at: Date.now() });
      await page.next((m) => m.type === "pong");
    }
    hidden.listen((m) => m.type === "ping" && hidden.send({ type: "ping", at: Date.now() }));
    await until(() => gone.closed !== null, "the runtime dropped the silent page", PAGE_GONE_AFTER_MS * 3);
    expect(gone.closed).toEqual({
      code: 4408,
      reason: `This page sent nothing for ${PAGE_GONE_AFTER_MS / 1000} s, so its connection was closed.`,
    });
    expect(hidden.closed).toBeNull();
    expect(hidden.messages.filter((m) => m.type === "ping").length).toBeGreaterThan(0);
    hidden.close();
  });
});
