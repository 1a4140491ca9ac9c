// The robot plugins this server knows, loaded once through the public loader
// from plugins/ (the same files and checks as any third-party plugin).
import { join } from "node:path";
import type { Plugin } from "@/core/plugins";
import { loadPluginFolder, type PluginFolder } from "@/robots/plugin-folder";

export const PLUGINS_DIR = join(process.cwd(), "plugins");

let loading: Promise<PluginFolder> | null = null;

export function pluginCatalog(): Promise<PluginFolder> {
  loading ??= loadPluginFolder(PLUGINS_DIR);
  return loading;
}

export async function findPlugin(robotId: string): Promise<Plugin | undefined> {
  return (await pluginCatalog()).plugins.find((p) => p.robotId === robotId);
}
