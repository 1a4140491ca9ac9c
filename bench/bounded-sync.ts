// bench/bounded-sync: what refusing a hostile file costs a sync. Each case is
// a repository of one plugin file served over loopback HTTP; fetchRepository
// refuses it (the figures before the limits, from issue 26: an endless body
// 10 s and 64 MB, a schema nested 10,000 levels 3.2 s and ~1 GB, a payload
// nested 10,000 levels a failed sync). Time from the start of the sync to its
// report; memory as the most the process's resident set grew meanwhile.
// Takes a few seconds.
import { createServer } from "node:http";
import type { AddressInfo } from "node:net";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { fetchRepository } from "../src/robots/repository-sync";
import { report } from "./support";

/** Each figure's count: a p99 is quoted, so at least 100. */
const RUNS = 100;
const LEVELS = 10_000;
const base = JSON.parse(
  readFileSync(join(import.meta.dirname, "..", "tests", "fixtures", "plugins", "base.json"), "utf8"),
);
const plugin = (extra: string) =>
  JSON.stringify({ ...base, robotId: "bench-bot", marker: "here" }).replace('"here"', extra);
const deepPayload = plugin(`${"[".repeat(LEVELS)}0${"]".repeat(LEVELS)}`);
const deepSchema = plugin(
  `${'{"type":"object","properties":{"a":'.repeat(LEVELS)}{"type":"string"}${"}}".repeat(LEVELS)}`,
);
const FIFTY_MB = 50 * 1024 * 1024;
const chunk = Buffer.alloc(64 * 1024, " ");

const server = createServer((req, res) => {
  // /<case>/repository.json, /<case>/plugins/index.json, /<case>/plugins/<case>.json
  const [, name, file, inPlugins] = req.url!.split("/");
  if (file === "repository.json") return res.end(JSON.stringify({ id: "bench", name: "Bench" }));
  if (inPlugins === "index.json") return res.end(JSON.stringify([`${name}.json`]));
  if (name === "deep-payload") return res.end(deepPayload);
  if (name === "deep-schema") return res.end(deepSchema);
  // 50 MB written as the socket takes it (the server runs in this process: its buffers count too).
  if (name === "declared-50mb" || name === "chunked-50mb") {
    res.writeHead(
      200,
      name === "declared-50mb" ? { "content-length": String(FIFTY_MB) } : { "transfer-encoding": "chunked" },
    );
    let sent = 0;
    const more = () => {
      while (!res.destroyed && sent < FIFTY_MB) {
        sent += chunk.length;
        if (!res.write(chunk)) return;
      }
      if (sent >= FIFTY_MB) res.end();
    };
    res.on("drain", more);
    return more();
  }
  if (name === "endless") {
    const more = () => {
      while (!res.destroyed) if (!res.write(chunk)) return;
    };
    res.on("drain", more);
    return more();
  }
  res.writeHead(404).end();
});
await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
const root = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;

for (const name of ["deep-payload", "deep-schema", "declared-50mb", "chunked-50mb", "endless"]) {
  const times: number[] = [];
  let grew = 0;
  let codes = "";
  for (let i = 0; i < RUNS; i++) {
    Bun.gc(true);
    const before = process.memoryUsage().rss;
    let peak = before;
    const sampler = setInterval(() => (peak = Math.max(peak, process.memoryUsage().rss)), 1);
    const started = performance.now();
    const result = await fetchRepository(`${root}/${name}/`);
    times.push(performance.now() - started);
    clearInterval(sampler);
    peak = Math.max(peak, process.memoryUsage().rss);
    grew = Math.max(grew, peak - before);
    codes = result.errors.map((e) => e.code).join(",");
  }
  report(`${name}: refused (${codes})`, times);
  console.log(`${"".padEnd(58)} most the resident set grew: ${(grew / 1024 / 1024).toFixed(1)} MB`);
}
server.closeAllConnections();
server.close();
process.exit(0);
