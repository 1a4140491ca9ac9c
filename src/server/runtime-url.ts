import type { Config } from "@/store/config";

/** Where browsers reach the trial runtime: HRI_RUNTIME_URL, or this host at HRI_RUNTIME_PORT. */
export function browserRuntimeUrl(config: Config): string {
  return (
    config.HRI_RUNTIME_URL ?? `ws://${config.HOST === "0.0.0.0" ? "localhost" : config.HOST}:${config.HRI_RUNTIME_PORT}`
  );
}
