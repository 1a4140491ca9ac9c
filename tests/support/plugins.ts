// A first-party plugin file of this repository (plugins/), loaded as the
// platform loads it: for tests that drive the simulated robot through it.
import { readFileSync } from "node:fs";
import { loadPlugin, type Plugin } from "../../src/core/plugins";

export function firstPartyPlugin(file: string): Plugin {
  const loaded = loadPlugin(file, readFileSync(`plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(`plugins/${file} does not load`);
  return loaded.value as Plugin;
}
