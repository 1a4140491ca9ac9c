// Builds the Next.js app when its sources changed since the last build.
import { spawnSync } from "node:child_process";
import { createHash } from "node:crypto";
import { existsSync, readdirSync, readFileSync, statSync, writeFileSync } from "node:fs";
import { join } from "node:path";

const INPUTS = [
  "src",
  "next.config.ts",
  "postcss.config.mjs",
  "tsconfig.json",
  "tsconfig.app.json",
  "package.json",
  "bun.lock",
  "plugins",
];

function fingerprint(root: string): string {
  const hash = createHash("sha256");
  const visit = (path: string) => {
    if (!existsSync(path)) return;
    const stat = statSync(path);
    if (stat.isDirectory()) {
      for (const name of readdirSync(path).sort()) visit(join(path, name));
    } else if (!path.endsWith(".test.ts")) {
      hash.update(path).update(readFileSync(path));
    }
  };
  for (const input of INPUTS) visit(join(root, input));
  return hash.digest("hex");
}

export function nextBin(root: string) {
  return join(root, "node_modules", "next", "dist", "bin", "next");
}

/** Returns false when the build failed (its output has been shown). */
export function buildIfChanged(root: string, log: (line: string) => void): boolean {
  const stampFile = join(root, ".next", "hristudio-build");
  const wanted = fingerprint(root);
  if (
    existsSync(join(root, ".next", "BUILD_ID")) &&
    existsSync(stampFile) &&
    readFileSync(stampFile, "utf8") === wanted
  ) {
    return true;
  }
  log("Building the web app (first start, or the code changed); this takes a minute…");
  const result = spawnSync(process.execPath.endsWith("bun") ? "node" : process.execPath, [nextBin(root), "build"], {
    cwd: root,
    stdio: "inherit",
    env: { ...process.env, NEXT_TELEMETRY_DISABLED: "1" },
  });
  if (result.status !== 0) return false;
  writeFileSync(stampFile, wanted);
  return true;
}
