// The layering, checked on the repository's own imports; the checker itself
// is shown to catch each kind of wrong arrow on graphs made up to break it.
import { describe, expect, it } from "vitest";
import { importGraph } from "./import-graph";
import { violations, type ImportEdge } from "./layers";

const value = (from: string, to: string): ImportEdge => ({ from, to, typeOnly: false });
const types = (from: string, to: string): ImportEdge => ({ from, to, typeOnly: true });

describe("architecture", () => {
  it("every import in src goes the way the layers allow", () => {
    const graph = importGraph();
    expect(graph.length).toBeGreaterThan(500);
    expect(violations(graph)).toEqual([]);
  });

  it.each([
    ["the core importing the data layer", value("src/core/trial/engine.ts", "src/store/client")],
    ["the core importing a package with I/O", value("src/core/trial/engine.ts", "postgres")],
    ["the core importing a server's types", types("src/core/trial/engine.ts", "src/server/api/trpc")],
    ["the data layer importing the server", value("src/store/event-store.ts", "src/server/audit")],
    ["the data layer importing the runtime", value("src/store/event-store.ts", "src/runtime/relay")],
    ["the data layer importing robots", value("src/store/event-store.ts", "src/robots/catalog")],
    ["robots importing the server", value("src/robots/catalog.ts", "src/server/config")],
    ["the runtime importing the web server", value("src/runtime/server.ts", "src/server/trials/files")],
    ["the web server importing the runtime", value("src/server/api/routers/trials.ts", "src/runtime/relay")],
    ["the server importing a feature", value("src/server/context.ts", "src/features/auth/sign-in-form")],
    ["the server importing React", value("src/server/context.ts", "react")],
    ["the runtime importing Next.js", value("src/runtime/server.ts", "next/headers")],
    ["a feature importing the runtime", value("src/features/execution/use-trial-socket.ts", "src/runtime/server")],
    ["a feature importing server code", value("src/features/auth/session.ts", "src/server/context")],
    ["a feature importing the data layer", types("src/features/analysis/analysis-page.tsx", "src/store/event-store")],
    ["a feature importing the app", value("src/features/shell/top-bar.tsx", "src/app/layout")],
    ["shared UI importing a feature", value("src/ui/table.tsx", "src/features/shell/top-bar")],
    ["the browser's clients importing shared UI", value("src/lib/trpc.tsx", "src/ui/button")],
    ["the browser's API client importing server values", value("src/lib/trpc.tsx", "src/server/http/body-limit")],
    ["the launcher importing the app", value("src/launcher/start.ts", "src/app/layout")],
    ["a file in no layer", value("src/tools/x.ts", "src/core/trial")],
    ["an import of a folder in no layer", value("src/server/context.ts", "src/tools/x")],
  ])("refuses %s", (_, edge) => {
    expect(violations([edge])).toHaveLength(1);
  });

  it.each([
    ["the data layer importing the core", value("src/store/event-store.ts", "src/core/trial")],
    ["robots importing the data layer", value("src/robots/catalog.ts", "src/store/schema")],
    ["the runtime importing data, core and robots", value("src/runtime/trial-hosts.ts", "src/robots/trial-plugin")],
    ["the core importing the plugin schema", value("src/core/plugins/schema.ts", "plugins/plugin.schema.json")],
    ["the browser's API client importing the router's type", types("src/lib/trpc.tsx", "src/server/api/root")],
    ["a route importing the server", value("src/app/api/trpc/[trpc]/route.ts", "src/server/api/root")],
    ["the request proxy importing the server", value("src/proxy.ts", "src/server/http/security-headers")],
    ["a feature importing shared UI", value("src/features/shell/top-bar.tsx", "src/ui/button")],
    ["the server importing a package", value("src/server/context.ts", "better-auth")],
  ])("allows %s", (_, edge) => {
    expect(violations([edge])).toEqual([]);
  });
});
