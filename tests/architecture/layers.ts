// The layers and the arrows allowed between them, and a pure check of an
// import graph against them. The graph is read from the files elsewhere
// (import-graph.ts), so the rules are tested on graphs made up to break them.

/** One import: the importing file, what it names (a path from the root, or a package), and whether only types cross. */
export interface ImportEdge {
  from: string;
  to: string;
  typeOnly: boolean;
}

export type Layer = keyof typeof LAYERS;

// Each layer: the paths it owns and the layers it may import besides itself.
// Lower layers first; nothing imports a layer above it.
export const LAYERS = {
  // Pure computation; the plugin schema is part of the core's declarations.
  core: { paths: ["src/core/", "plugins/plugin.schema.json"], imports: [] },
  // What both servers stand on: the database, the event store, study access, socket tokens, config, error references.
  store: { paths: ["src/store/"], imports: ["core"] },
  // Plugin loading and the catalog (which reads installed plugins), transports, the simulated robot.
  robots: { paths: ["src/robots/"], imports: ["core", "store"] },
  server: { paths: ["src/server/"], imports: ["core", "store", "robots"] },
  runtime: { paths: ["src/runtime/"], imports: ["core", "store", "robots"] },
  launcher: { paths: ["src/launcher/"], imports: ["core", "store", "server"] },
  // The browser side. Routes and pages compose features and the server's handlers.
  app: { paths: ["src/app/", "src/proxy.ts"], imports: ["core", "store", "server", "features", "ui", "lib"] },
  features: { paths: ["src/features/"], imports: ["core", "ui", "lib"] },
  // Shared components may use the browser's clients (the API, auth); the clients use no components.
  ui: { paths: ["src/ui/"], imports: ["core", "lib"] },
  lib: { paths: ["src/lib/"], imports: ["core"] },
} as const satisfies Record<string, { paths: readonly string[]; imports: readonly string[] }>;

const BROWSER: readonly Layer[] = ["features", "lib", "ui"];
// The launcher is left out: it is the process that starts Next.js.
const SERVER_SIDE: readonly Layer[] = ["store", "robots", "server", "runtime"];

// What the core may use from packages: computation only.
const PURE_PACKAGES = new Set(["zod", "ajv", "node:crypto"]);
const isUiPackage = (name: string) =>
  ["react", "react-dom", "next"].includes(name) || name.startsWith("react-dom/") || name.startsWith("next/");

const isOurs = (path: string) => path.startsWith("src/") || path.startsWith("plugins/");

export function layerOf(path: string): Layer | null {
  for (const [layer, { paths }] of Object.entries(LAYERS)) {
    if (paths.some((p) => (p.endsWith("/") ? path.startsWith(p) : path === p || path.startsWith(`${p}.`))))
      return layer as Layer;
  }
  return null;
}

/** Why an import breaks the layering, or null when it is allowed. */
export function violation({ from, to, typeOnly }: ImportEdge): string | null {
  const source = layerOf(from);
  if (source === null) return `${from} is in no layer: add its folder to LAYERS`;
  if (!isOurs(to)) {
    if (source === "core" && !PURE_PACKAGES.has(to)) return `${from} (core) imports the package ${to}`;
    if (SERVER_SIDE.includes(source) && isUiPackage(to))
      return `${from} (${source}) imports the user-interface package ${to}`;
    return null;
  }
  const target = layerOf(to);
  if (target === null) return `${from} imports ${to}, which is in no layer`;
  if (target === source || (LAYERS[source].imports as readonly Layer[]).includes(target)) return null;
  // Types are erased at build: the browser may know the API's types (the tRPC router's) but no server code.
  if (typeOnly && BROWSER.includes(source) && target === "server") return null;
  return `${from} (${source}) imports ${to} (${target})`;
}

export const violations = (graph: readonly ImportEdge[]): string[] =>
  graph.map(violation).filter((v): v is string => v !== null);
