// The web server (web-server.ts) must run under Node, as Next.js expects, but
// Node 20 cannot run TypeScript: the launcher, under bun, bundles it into one
// ES module first. Packages stay external and load from node_modules; the
// bundle lives under .next so that `next` and `zod` resolve from the root.
import { join } from "node:path";

export async function bundleWebServer(root: string): Promise<string> {
  const outdir = join(root, ".next", "hristudio");
  const result = await Bun.build({
    entrypoints: [join(root, "src", "launcher", "web-server.ts")],
    outdir,
    target: "node",
    format: "esm",
    packages: "external",
    naming: "[name].mjs",
  });
  if (!result.success) throw new Error(`The web server could not be bundled:\n${result.logs.map(String).join("\n")}`);
  return join(outdir, "web-server.mjs");
}
