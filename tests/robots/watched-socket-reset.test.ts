// A lost bridge link is reset, not closed politely (issue 25): the bridge's
// side sees the connection reset (a TCP RST), which throws away whatever our
// side still queued for it, where a close (FIN) would deliver that first.
import type { AddressInfo } from "node:net";
import { afterEach, expect, it } from "vitest";
import { WebSocketServer } from "ws";
import { WatchedSocket } from "../../src/robots/transports/watched-socket";

let server: WebSocketServer | null = null;
afterEach(() => {
  server?.close();
  server = null;
});

it("a link given up is reset: the bridge's side reads ECONNRESET, not an orderly end", async () => {
  server = new WebSocketServer({ port: 0, host: "127.0.0.1" });
  await new Promise((ok) => server!.once("listening", ok));
  const ended = new Promise<string>((resolve) =>
    server!.once("connection", (_ws, request) => {
      request.socket.on("error", (error: NodeJS.ErrnoException) => resolve(error.code ?? "error"));
      request.socket.on("end", () => resolve("orderly end"));
    }),
  );
  const socket = new WatchedSocket(
    `ws://127.0.0.1:${(server.address() as AddressInfo).port}`,
    { everyMs: 500, timeoutMs: 1500 },
    () => {},
  );
  await new Promise((ok) => socket.on("open", ok));
  socket.terminate("the robot's bridge stopped answering");
  expect(await ended).toBe("ECONNRESET");
});
