// Fetches a plugin repository over HTTP the way HRIStudio publishes one:
// repository.json, plugins/index.json, then each plugin file. Every file goes
// through the public loader; a bad plugin is reported and the rest are kept.
// Storing the result and showing the changes is the server's job.
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
  plugins: FetchedPlugin[];
  errors: PluginError[];
}

const MAX_BYTES = 1_000_000;

export async function fetchRepository(
  baseUrl: string,
  fetchFn: typeof fetch = fetch,
  timeoutMs = 10_000,
): Promise<FetchedRepository> {
  const base = baseUrl.endsWith("/") ? baseUrl : `${baseUrl}/`;
  const result: FetchedRepository = { repository: null, plugins: [], errors: [] };
  const get = async (path: string): Promise<string | null> => {
    try {
      const response = await fetchFn(new URL(path, base), { signal: AbortSignal.timeout(timeoutMs) });
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      const text = await response.text();
      if (text.length > MAX_BYTES) throw new Error(`larger than ${MAX_BYTES} bytes`);
      return text;
    } catch (error) {
      result.errors.push({
        file: path,
        path: "",
        code: "unreadable",
        reason: `cannot fetch ${new URL(path, base)}: ${(error as Error).message}`,
      });
      return null;
    }
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
