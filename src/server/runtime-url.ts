import type { Config } from "@/store/config";

/** Where browsers reach the trial runtime: HRI_RUNTIME_URL, or this host at HRI_RUNTIME_PORT. */
export function browserRuntimeUrl(config: Config): string {
  return (
    config.HRI_RUNTIME_URL ?? `ws://${config.HOST === "0.0.0.0" ? "localhost" : config.HOST}:${config.HRI_RUNTIME_PORT}`
  );
}

/** Where people reach the app itself: BETTER_AUTH_URL, or this host at PORT. */
export function appUrl(config: Config): string {
  return (
    config.BETTER_AUTH_URL ?? `http://${config.HOST === "0.0.0.0" ? "localhost" : config.HOST}:${config.PORT ?? 3000}`
  );
}
