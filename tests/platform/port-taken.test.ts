// An app whose web port is taken as it starts stops with EADDRINUSE; the tests'
// startApp says so at once (it does not wait its two minutes for an answer).
// On ports it chose itself it starts the app again on others (see app.ts); a
// port the test named is the test's, and its refusal comes back at once.
import { createServer, type Socket } from "node:net";
import { afterAll, expect, it } from "vitest";
import { startApp } from "../support/app";
import { freePort } from "../../src/store/embedded";

// Another program on the port: it takes connections and never answers them.
const connections = new Set<Socket>();
const held = createServer((socket) => connections.add(socket));
const port = await freePort();
await new Promise<void>((ok) => held.listen(port, "127.0.0.1", ok));
afterAll(() => {
  for (const socket of connections) socket.destroy();
  held.close();
});

it("refuses, in the app's own words, a start on a web port another program holds", async () => {
  const refusal = await startApp({ env: { PORT: String(port) } }).then(
    (app) => app.stop().then(() => null),
    (error: Error) => error.message,
  );
  expect(refusal).toMatch(/EADDRINUSE/);
  expect(refusal).toMatch(new RegExp(`127\\.0\\.0\\.1:${port}`));
}, 180_000);
