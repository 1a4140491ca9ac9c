// Fetches a plugin repository over HTTP the way HRIStudio publishes one:
// repository.json, plugins/index.json, then each plugin file. Every file goes
// through the public loader; a bad plugin is reported and the rest are kept.
// Every file is read with a limit counted while it arrives (an endless body
// stops at the limit) and refused if it nests deeper than the loader's limit,
// before anything is built from it. Storing the result and showing the
// changes is the server's job.
import { readWithin, sizeText } from "../core/network/bounded-body";
import { MB } from "../core/network/limits";
import {
  effectiveTrust,
  loadPlugin,
  parsePluginIndex,
  parseRepository,
  type Plugin,
  type PluginError,
  type PluginRepository,
  type TrustLevel,
} from "../core/plugins";

export interface FetchedPlugin {
  file: string;
  plugin: Plugin;
  /** The lower of the repository's trust and the plugin's own claim. */
  trust: TrustLevel;
}

export interface FetchedRepository {
  repository: PluginRepository | null;
  /** The files plugins/index.json lists; null when it could not be read, so nothing is known to be gone. */
  index: string[] | null;
  plugins: FetchedPlugin[];
  errors: PluginError[];
}

/** The most a repository's file may be; HRIStudio's largest is 12 KB, ours 21 KB. */
export const MAX_FILE_BYTES = MB;

export async function fetchRepository(
  baseUrl: string,
  fetchFn: typeof fetch = fetch,
  timeoutMs = 10_000,
): Promise<FetchedRepository> {
  const base = baseUrl.endsWith("/") ? baseUrl : `${baseUrl}/`;
  const result: FetchedRepository = { repository: null, index: null, plugins: [], errors: [] };
  const get = async (path: string): Promise<string | null> => {
    const url = new URL(path, base);
    try {
      const response = await fetchFn(url, { signal: AbortSignal.timeout(timeoutMs) });
      if (!response.ok) {
        await response.body?.cancel().catch(() => {});
        throw new Error(`HTTP ${response.status}`);
      }
      const read = await readWithin(response, MAX_FILE_BYTES);
      if (read.ok) return new TextDecoder().decode(read.bytes);
      const size = read.declared === undefined ? "" : ` (it says ${sizeText(read.declared)})`;
      result.errors.push({
        file: path,
        path: "",
        code: "too_large",
        reason: `${url} is larger than ${sizeText(MAX_FILE_BYTES)}, the most a repository's file may be${size}: reading stopped at the limit`,
      });
    } catch (error) {
      result.errors.push({
        file: path,
        path: "",
        code: "unreadable",
        reason: `cannot fetch ${url}: ${(error as Error).message}`,
      });
    }
    return null;
  };
  const repositoryText = await get("repository.json");
  if (repositoryText === null) return result;
  const repository = parseRepository("repository.json", repositoryText);
  if (!repository.ok) return { ...result, errors: [...result.errors, ...repository.errors] };
  result.repository = repository.value;
  const indexText = await get("plugins/index.json");
  if (indexText === null) return result;
  const index = parsePluginIndex("plugins/index.json", indexText);
  if (!index.ok) return { ...result, errors: [...result.errors, ...index.errors] };
  result.index = index.value;
  for (const name of index.value) {
    const text = await get(`plugins/${name}`);
    if (text === null) continue;
    const loaded = loadPlugin(name, text);
    if (!loaded.ok) result.errors.push(...loaded.errors);
    else
      result.plugins.push({
        file: name,
        plugin: loaded.value,
        trust: effectiveTrust(repository.value.trust, loaded.value.trustLevel),
      });
  }
  return result;
}
