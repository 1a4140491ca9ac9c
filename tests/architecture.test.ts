// The layout's rules, checked: the pure core reaches no I/O and nothing
// outside itself, and imports go one way (core ← server, runtime, robots ← app).
import { readdirSync, readFileSync, statSync } from "node:fs";
import { join, normalize, relative, dirname } from "node:path";
import { describe, expect, it } from "vitest";

const root = join(import.meta.dirname, "..");

function sources(dir: string): string[] {
  return readdirSync(join(root, dir)).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(join(root, path)).isDirectory()) return sources(path);
    return /\.tsx?$/.test(name) && !name.includes(".test.") ? [path] : [];
  });
}

/** Every import of a file, as a path from the repository root (or a package name). */
function importsOf(file: string): string[] {
  const text = readFileSync(join(root, file), "utf8");
  return [...text.matchAll(/(?:from|import)\s+"([^"]+)"/g)].map((m) => {
    const target = m[1]!;
    if (target.startsWith("@/")) return normalize(join("src", target.slice(2)));
    if (target.startsWith(".")) return normalize(relative(root, join(root, dirname(file), target)));
    return target;
  });
}

// What the core may use: computation only.
const PURE_PACKAGES = new Set(["zod", "ajv", "node:crypto"]);

describe("architecture", () => {
  it("keeps src/core pure: no I/O, nothing of ours outside the core", () => {
    for (const file of sources("src/core")) {
      for (const target of importsOf(file)) {
        const ours = target.startsWith("src/") || target.startsWith("plugins/");
        const allowed = ours ? target.startsWith("src/core/") || target === "plugins/plugin.schema.json" : PURE_PACKAGES.has(target);
        expect(allowed, `${file} imports ${target}`).toBe(true);
      }
    }
  });

  it("keeps the server, runtime and robots free of the user interface", () => {
    for (const dir of ["src/server", "src/runtime", "src/robots"]) {
      for (const file of sources(dir)) {
        for (const target of importsOf(file)) {
          const ui = ["src/app", "src/features", "src/ui", "src/lib"].some((d) => target.startsWith(d)) || target === "react" || target.startsWith("next/");
          expect(ui, `${file} imports ${target}`).toBe(false);
        }
      }
    }
  });
});
