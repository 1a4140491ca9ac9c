// Loads every plugin file in a folder through the public loader. Fail soft:
// a bad file is reported with its errors and the good ones are kept, the way
// Node-RED marks a node unavailable and keeps running.
import { readdir, readFile } from "node:fs/promises";
import { join } from "node:path";
import { loadPlugin, type Plugin, type PluginError } from "../core/plugins";

/** Files in a plugins folder that are not plugins. */
const NOT_PLUGINS = new Set(["plugin.schema.json", "index.json", "repository.json"]);

export interface PluginFolder {
  plugins: Plugin[];
  /** Where each plugin came from, by robotId. */
  files: Record<string, string>;
  errors: PluginError[];
}

export async function loadPluginFolder(folder: string): Promise<PluginFolder> {
  const result: PluginFolder = { plugins: [], files: {}, errors: [] };
  let names: string[];
  try {
    names = (await readdir(folder)).filter((n) => n.endsWith(".json") && !NOT_PLUGINS.has(n)).sort();
  } catch (error) {
    result.errors.push({ file: folder, path: "", code: "unreadable", reason: (error as Error).message });
    return result;
  }
  for (const name of names) {
    let text: string;
    try {
      text = await readFile(join(folder, name), "utf8");
    } catch (error) {
      result.errors.push({ file: name, path: "", code: "unreadable", reason: (error as Error).message });
      continue;
    }
    const loaded = loadPlugin(name, text);
    if (!loaded.ok) {
      result.errors.push(...loaded.errors);
      continue;
    }
    const earlier = result.files[loaded.value.robotId];
    if (earlier) {
      result.errors.push({
        file: name,
        path: "/robotId",
        code: "duplicate_robot",
        reason: `robotId "${loaded.value.robotId}" is already declared by ${earlier}`,
      });
      continue;
    }
    result.files[loaded.value.robotId] = name;
    result.plugins.push(loaded.value);
  }
  return result;
}
