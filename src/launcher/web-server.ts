// The web app's HTTP server, in place of `next start` / `next dev`: Next.js's
// own request handler behind a plain Node server, because only here is the
// socket visible. Before Next.js sees a request, the client's address (the
// socket, or what trusted proxies vouch for) goes into one header that only
// this server sets; sign-in limits and session records read that header.
// What no route or page may be sent (src/core/network/request-gate.ts) is
// refused here too, before Next.js reads any of it. It also finishes
// recordings whose page went away (left-over.ts), at start and every little
// while after. The launcher bundles this file for Node (see web-bundle.ts)
// and runs it as `node web-server.mjs [--dev]`.
import { createServer } from "node:http";
import next from "next";
import { CLIENT_ADDRESS_HEADER, clientAddress } from "../core/network/client-address";
import { readConfig } from "../store/config";
import { refused } from "../server/http/request-gate";
import { appUrl } from "../server/runtime-url";
import { createDatabase } from "../store/client";
import { configuredMedia } from "../server/media";
import { keepFinishingLeftOver } from "../server/media/left-over";

const dev = process.argv.includes("--dev");
const dir = process.cwd();
const config = readConfig();
const port = config.PORT ?? 3000;
// Where the app's pages are served from, as the sign-in library knows it.
const origin = appUrl(config);

const app = next({ dev, dir, hostname: config.HOST, port });
const handle = app.getRequestHandler();

await app.prepare();
const server = createServer((req, res) => {
  if (refused(req, res, origin)) return;
  req.headers[CLIENT_ADDRESS_HEADER] = clientAddress({
    socketAddress: req.socket.remoteAddress,
    forwardedFor: req.headers["x-forwarded-for"],
    trustedProxies: config.HRI_TRUSTED_PROXIES,
  });
  void handle(req, res);
});
server.listen(port, config.HOST);

if (config.DATABASE_URL) {
  const { db } = createDatabase(config.DATABASE_URL, { max: 2 });
  keepFinishingLeftOver(db, configuredMedia(config), (line) => console.log(`[hristudio] ${line}`));
}

// Stopped by the launcher (or by a later launcher, for an orphan): exit at once,
// as `next start` does; requests in flight are not waited for.
const exit = () => process.exit(0);
process.on("SIGTERM", exit);
process.on("SIGINT", exit);
