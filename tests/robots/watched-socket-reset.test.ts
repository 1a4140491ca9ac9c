// A lost bridge link is reset, not closed politely (issue 25): the bridge's
// side sees the connection reset (a TCP RST), which throws away whatever our
// side still queued for it, where a close (FIN) would deliver that first.
import { spawn } from "node:child_process";
import type { AddressInfo } from "node:net";
import { afterEach, expect, it } from "vitest";
import { WebSocketServer } from "ws";
import { WatchedSocket } from "../../src/robots/transports/watched-socket";
import { BUN } from "../support/app";

let server: WebSocketServer | null = null;
afterEach(() => {
  server?.close();
  server = null;
});

/** A bridge that reports how its connection ended: reset, or an orderly end. */
async function bridge() {
  server = new WebSocketServer({ port: 0, host: "127.0.0.1" });
  await new Promise((ok) => server!.once("listening", ok));
  const ended = new Promise<string>((resolve) =>
    server!.once("connection", (_ws, request) => {
      request.socket.on("error", (error: NodeJS.ErrnoException) => resolve(error.code ?? "error"));
      request.socket.on("end", () => resolve("orderly end"));
    }),
  );
  return { url: `ws://127.0.0.1:${(server.address() as AddressInfo).port}`, ended };
}

it("a link given up is reset: the bridge's side reads ECONNRESET, not an orderly end", async () => {
  const { url, ended } = await bridge();
  const socket = new WatchedSocket(url, { everyMs: 500, timeoutMs: 1500 }, () => {});
  await new Promise((ok) => socket.on("open", ok));
  socket.terminate("the robot's bridge stopped answering");
  expect(await ended).toBe("ECONNRESET");
});

it("is reset under Bun as well, where the runtime runs (Bun's own ws client keeps no socket to reset)", async () => {
  const { url, ended } = await bridge();
  const probe = spawn(BUN, ["run", "tests/robots/support/reset-link.ts", url], { stdio: "ignore" });
  expect(await ended).toBe("ECONNRESET");
  await new Promise((exited) => (probe.exitCode === null ? probe.once("exit", exited) : exited(null)));
});
