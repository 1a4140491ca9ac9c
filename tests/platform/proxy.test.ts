// Several runtimes behind HAProxy, started from the configuration the docs
// give (deploy/haproxy.cfg, its addresses from the environment): a wizard's
// socket reaches a trial through it, and when one runtime is killed, the
// socket on the other keeps working and a page that connects again is sent
// to the one left, which runs the trial.
import { type ChildProcess, spawn } from "node:child_process";
import { existsSync } from "node:fs";
import { connect } from "node:net";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { freePort } from "../../src/store/embedded";
import { robotStudies, robots, studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { trialOf } from "../support/trial-rows";

const HAPROXY = "/usr/sbin/haproxy";
const CONFIG = join(import.meta.dirname, "..", "..", "deploy", "haproxy.cfg");
const SECRET = "proxy-test-secret".padEnd(40, "x");
const plugin = firstPartyPlugin("simulated.json");

const snapshot: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "Proxied", description: "", robotId: "simulated" },
  steps: ["Hello", "Goodbye"].map((text, i) => ({
    id: `s${i}`,
    name: text,
    description: "",
    actions: [{ id: `a${i}`, type: "say", name: "", parameters: { text }, parallelGroup: null }],
  })),
};

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 2 });
const runtimes: Array<Awaited<ReturnType<typeof startRuntime>>> = [];
const sockets: TrialSocket[] = [];
let proxy: ChildProcess | null = null;
let proxyUrl = "";
let sim: Simulator;
let wizardId = "";
let trialId = "";

/** Resolves once something accepts connections on the port. */
async function accepting(port: number) {
  for (;;) {
    const ok = await new Promise<boolean>((done) => {
      const socket = connect(port, "127.0.0.1", () => {
        socket.end();
        done(true);
      });
      socket.once("error", () => done(false));
    });
    if (ok) return;
    await new Promise((r) => setTimeout(r, 50));
  }
}

beforeAll(async () => {
  if (!existsSync(HAPROXY))
    throw new Error("HAProxy is needed for the proxy test: apt-get install haproxy (npm test installs it as root).");
  const [study] = await db.insert(studies).values({ title: "Proxied", status: "active" }).returning();
  wizardId = (
    await createAccount(db, { name: "Wizard", email: "w@example.org", password: "password-123", role: "researcher" })
  ).id;
  await db.insert(studyMembers).values({ studyId: study!.id, userId: wizardId, role: "wizard" });
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  const [robot] = await db.insert(robots).values({ name: "Sim", simulated: true, rosbridgeUrl: sim.url }).returning();
  await db.insert(robotStudies).values({ robotId: robot!.id, studyId: study!.id });
  trialId = await trialOf(db, { studyId: study!.id, wizardId, snapshot });
  for (let i = 0; i < 2; i++) runtimes.push(await startRuntime(url, SECRET));
  const port = await freePort();
  proxy = spawn(HAPROXY, ["-db", "-f", CONFIG], {
    env: {
      ...process.env,
      HRI_PROXY_BIND: `127.0.0.1:${port}`,
      HRI_RUNTIME_1: runtimes[0]!.url.replace("ws://", ""),
      HRI_RUNTIME_2: runtimes[1]!.url.replace("ws://", ""),
    },
    stdio: "ignore",
  });
  await accepting(port);
  proxyUrl = `ws://127.0.0.1:${port}`;
}, 120_000);

afterAll(async () => {
  for (const s of sockets) s.close();
  proxy?.kill("SIGKILL");
  for (const r of runtimes) r.child.kill("SIGKILL");
  await sim?.close();
  await close();
});

async function page() {
  const socket = await connectTrial(proxyUrl, signSocketToken({ userId: wizardId, trialId }, SECRET));
  sockets.push(socket);
  expect(socket.messages.map((m) => m.type)).toContain("welcome");
  return socket;
}

const said = () =>
  sim.received
    .filter((r) => r.message.op === "publish" && r.message.topic === "/speech")
    .map((r) => (r.message.msg as { data: string }).data);

describe.sequential("several runtimes behind HAProxy (deploy/haproxy.cfg)", () => {
  it("carries a wizard's socket to a trial, and keeps the trial running when one runtime is killed", {
    timeout: 60_000,
  }, async () => {
    // The docs' check: a plain request through the proxy is answered by a runtime.
    const plain = await fetch(proxyUrl.replace("ws://", "http://"));
    expect([plain.status, await plain.text()]).toEqual([
      426,
      "This is the HRIStudio trial runtime: connect with a WebSocket.",
    ]);
    // Two pages: the proxy gives each runtime one (the fewest sockets first).
    const pages = [await page(), await page()];
    expect(await pages[0]!.command("start", { kind: "start" })).toMatchObject({ type: "ack" });
    expect(await pages[1]!.command("hello", { kind: "next" })).toMatchObject({ type: "ack" });
    await expect.poll(said).toEqual(["Hello"]);

    const killed = runtimes[0]!.child;
    await new Promise((exited) => {
      killed.once("exit", exited);
      killed.kill("SIGKILL");
    });
    // The page on the killed runtime lost its socket; the other's goes on.
    await expect.poll(() => pages.filter((p) => p.closed).length).toBe(1);
    const left = pages.find((p) => !p.closed)!;
    expect(await left.command("note", { kind: "note", text: "Still here" })).toMatchObject({ type: "ack" });
    // The page that lost its socket connects again through the proxy: to the runtime left, which runs the trial.
    const again = await page();
    expect(await again.command("on", { kind: "next" })).toMatchObject({ type: "ack" });
    expect(await again.command("bye", { kind: "next" })).toMatchObject({ type: "ack" });
    await expect.poll(said).toEqual(["Hello", "Goodbye"]);
  });
});
