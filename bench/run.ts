// `npm run bench [name…]`: runs the named benchmarks (all when none is named)
// one after another, each in its own process so none warms another.
import { spawnSync } from "node:child_process";
import { readdirSync } from "node:fs";
import { join } from "node:path";

const here = import.meta.dirname;
const all = readdirSync(here)
  .filter((f) => f.endsWith(".ts") && f !== "run.ts" && !f.startsWith("support"))
  .map((f) => f.replace(/\.ts$/, ""));
const wanted = process.argv.slice(2);
const unknown = wanted.filter((w) => !all.includes(w));
if (unknown.length) {
  console.error(`No benchmark named ${unknown.join(", ")}. Available: ${all.join(", ")}.`);
  process.exit(2);
}
let failed = false;
for (const name of wanted.length ? wanted : all) {
  console.log(`\n== ${name}`);
  const run = spawnSync(process.execPath, ["run", join(here, `${name}.ts`)], { stdio: "inherit" });
  failed ||= run.status !== 0;
}
process.exit(failed ? 1 : 0);
