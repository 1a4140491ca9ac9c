// The trial socket before hello, in the real runtime process: a frame larger
// than a hello is refused before it is read (40 connections each sending one
// 15 MB frame leave the runtime's memory where it was), a connection that
// never says hello is closed after the deadline, one address may hold only a
// few connections that have not said hello, and after hello a message larger
// than its kind allows is refused in plain words. Memory is read from
// /proc/<pid>/status (VmRSS), a behaviour, not a timing.
import type { ChildProcess } from "node:child_process";
import { readFileSync } from "node:fs";
import { connect } from "node:net";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import WebSocket from "ws";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { HELLO_DEADLINE_MS, UNGREETED_PER_ADDRESS } from "../../src/core/socket/limits";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { startRuntime } from "../support/runtime";
import { connectTrial } from "../support/socket";
import { trialOf } from "../support/trial-rows";

const SECRET = "socket-limits-test-secret".padEnd(40, "x");
const MB = 1024 * 1024;

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 2 });
let runtime: { url: string; child: ChildProcess };
const opened: WebSocket[] = [];

beforeAll(async () => {
  runtime = await startRuntime(url, SECRET);
}, 120_000);

afterAll(async () => {
  for (const ws of opened) ws.terminate();
  runtime?.child.kill("SIGKILL");
  await close();
});

/** The runtime's resident memory now, in bytes. */
function rss(): number {
  const status = readFileSync(`/proc/${runtime.child.pid}/status`, "utf8");
  return Number(/VmRSS:\s+(\d+) kB/.exec(status)![1]) * 1024;
}

interface Closed {
  code: number;
  reason: string;
}

/**
 * One text frame of `bytes` sent before hello, written as a client would (masked, here with a zero mask) from a
 * 64 KB piece again and again, so the test holds no 15 MB of its own. Resolves with the server's close frame.
 */
function oneFrame(bytes: number, localAddress: string): Promise<Closed> {
  const { hostname, port } = new URL(runtime.url);
  return new Promise((resolve, reject) => {
    const socket = connect({ host: hostname, port: Number(port), localAddress });
    const piece = Buffer.alloc(64 * 1024, "a");
    let answer = Buffer.alloc(0);
    let upgraded = false;
    let gone = false;
    socket.on("error", () => undefined); // the server may close while we still write: that is the point
    socket.on("close", () => {
      gone = true;
      if (!upgraded) reject(new Error("the runtime did not upgrade the connection"));
    });
    const write = async () => {
      const header = Buffer.alloc(14);
      header[0] = 0x81; // the whole message, text
      header[1] = 0x80 | 127; // masked, 64-bit length
      header.writeBigUInt64BE(BigInt(bytes), 2);
      socket.write(header); // the mask, 4 zero bytes, is the header's last four
      for (let sent = 0; sent < bytes && !gone; sent += piece.length) {
        if (!socket.write(piece.subarray(0, Math.min(piece.length, bytes - sent))))
          await new Promise((drained) => socket.once("drain", drained).once("close", drained));
      }
    };
    socket.on("data", (data) => {
      answer = Buffer.concat([answer, data]);
      if (!upgraded) {
        const end = answer.indexOf("\r\n\r\n");
        if (end < 0) return;
        if (!answer.subarray(0, end).toString().startsWith("HTTP/1.1 101")) return reject(new Error(answer.toString()));
        upgraded = true;
        answer = answer.subarray(end + 4);
        void write();
      }
      // The server's close frame: 0x88, its length, then the code and the reason.
      if (answer.length >= 2 && answer[0] === 0x88 && answer.length >= 2 + answer[1]!) {
        resolve({ code: answer.readUInt16BE(2), reason: answer.subarray(4, 2 + answer[1]!).toString() });
        socket.destroy();
      }
    });
    socket.write(
      [
        "GET / HTTP/1.1",
        `Host: ${hostname}:${port}`,
        "Upgrade: websocket",
        "Connection: Upgrade",
        `Sec-WebSocket-Key: ${Buffer.from("a sixteen bytes!").toString("base64")}`,
        "Sec-WebSocket-Version: 13",
        "",
        "",
      ].join("\r\n"),
    );
  });
}

/** A WebSocket from `localAddress` that says nothing unless told; resolves once open. */
async function silent(localAddress: string, headers: Record<string, string> = {}) {
  const ws = new WebSocket(runtime.url, { localAddress, headers });
  opened.push(ws);
  const closed = new Promise<Closed>((resolve) =>
    ws.once("close", (code, reason) => resolve({ code, reason: String(reason) })),
  );
  await new Promise((open, fail) => ws.once("open", open).once("error", fail));
  return { ws, closed };
}

// Plain words: a sentence, no stack, no code name.
const PLAIN = /^[A-Z][^\n]{10,200}$/;

describe("the trial socket before hello", () => {
  it("refuses 40 connections each sending a 15 MB frame before hello, each with a plain reason, in bounded memory", {
    timeout: 120_000,
  }, async () => {
    const before = rss();
    let most = before;
    const watch = setInterval(() => (most = Math.max(most, rss())), 20);
    // From 40 addresses (all loopback), so the limit per address does not close them first.
    const closes = await Promise.all(Array.from({ length: 40 }, (_, i) => oneFrame(15 * MB, `127.0.0.${i + 2}`)));
    clearInterval(watch);
    most = Math.max(most, rss());
    for (const closed of closes) {
      expect(closed.code).toBe(1009);
      expect(closed.reason).toMatch(/\w+ \w+/);
      expect(closed.reason).not.toMatch(/\n|\bat .*:\d+/);
    }
    expect(most - before).toBeLessThan(150 * MB);
  });

  it("closes a connection whose first frame is larger than a hello, saying so", async () => {
    expect(await oneFrame(100 * 1024, "127.0.0.100")).toEqual({
      code: 1009,
      reason:
        "The first message must be a hello of a few hundred bytes; this one had 100 KB, so the connection was closed.",
    });
  });

  it("closes a connection that says nothing, once the hello deadline has passed", { timeout: 30_000 }, async () => {
    const { closed } = await silent("127.0.0.101");
    expect(await closed).toEqual({
      code: 1008,
      reason: `No hello came within ${HELLO_DEADLINE_MS / 1000} s, so the connection was closed.`,
    });
  });

  it("lets one address hold only a few connections that have not said hello; others are not affected", {
    timeout: 30_000,
  }, async () => {
    const held = [];
    for (let i = 0; i < UNGREETED_PER_ADDRESS; i++) held.push(await silent("127.0.0.102"));
    // Naming another address of its own does not help: the runtime believes only the proxies it was told of.
    for (const headers of [{}, { "x-forwarded-for": "10.9.9.9" }] as Array<Record<string, string>>) {
      const closed = await (await silent("127.0.0.102", headers)).closed;
      expect(closed.code).toBe(1013);
      expect(closed.reason).toMatch(PLAIN);
      expect(closed.reason).toContain("Too many connections from your address have not said hello yet");
    }
    // Another address is let in, and so is this one once one of its connections has gone.
    const other = await silent("127.0.0.103");
    held[0]!.ws.close();
    await held[0]!.closed;
    const again = await silent("127.0.0.102");
    for (const { ws } of [other, again]) {
      ws.send(JSON.stringify({ type: "ping", at: Date.now() }));
      await new Promise((answered) => ws.once("message", answered));
    }
    for (const { ws } of [...held, other, again]) ws.terminate();
  });
});

describe("the trial socket after hello", () => {
  it("refuses a message larger than its kind allows in plain words, and goes on", { timeout: 60_000 }, async () => {
    const [study] = await db.insert(studies).values({ title: "Limits", status: "active" }).returning();
    const wizard = await createAccount(db, {
      name: "Wizard",
      email: "limits@example.org",
      password: "password-123",
      role: "researcher",
    });
    await db.insert(studyMembers).values({ studyId: study!.id, userId: wizard.id, role: "wizard" });
    const snapshot: ProtocolSnapshot = {
      schemaVersion: 5,
      experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
      steps: [{ id: "s1", name: "One", description: "", actions: [] }],
    };
    const trialId = await trialOf(db, { studyId: study!.id, wizardId: wizard.id, snapshot });
    const socket = await connectTrial(runtime.url, signSocketToken({ userId: wizard.id, trialId }, SECRET));
    expect(socket.messages.some((m) => m.type === "welcome")).toBe(true);

    const large = await socket.command("big", {
      kind: "unscripted",
      actionType: "say",
      parameters: { text: "a".repeat(100 * 1024) },
    });
    expect(large).toMatchObject({
      type: "rejected",
      reason: "That command message is too large (101 KB; at most 64 KB): nothing was done.",
    });
    expect((await socket.command("small", { kind: "note", text: "still here" })).type).toBe("ack");
    expect(socket.closed).toBeNull();
    socket.close();
  });
});
