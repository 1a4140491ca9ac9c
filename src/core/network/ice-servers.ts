// The STUN/TURN servers browsers use to reach each other for live video
// (HRI_ICE_SERVERS). None by default: on one local network the browsers find
// each other directly. A lab across networks or behind NAT sets one.
export interface IceServer {
  urls: string[];
  username?: string;
  credential?: string;
}

const SCHEME = /^(stun|stuns|turn|turns):[^\s]+$/;

/**
 * Reads the setting: a JSON array of RTCIceServer objects (for TURN with a
 * username and credential), or comma-separated stun:/turn: addresses.
 */
export function parseIceServers(setting: string): { servers: IceServer[] } | { error: string } {
  const text = setting.trim();
  if (!text) return { servers: [] };
  if (!text.startsWith("[")) {
    const urls = text
      .split(",")
      .map((u) => u.trim())
      .filter(Boolean);
    const wrong = urls.find((u) => !SCHEME.test(u));
    if (wrong) return { error: `"${wrong}" is not a stun: or turn: address (e.g. stun:stun.lab.example.org:3478).` };
    return { servers: urls.map((u) => ({ urls: [u] })) };
  }
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return { error: "it starts with [ but is not valid JSON." };
  }
  if (!Array.isArray(data)) return { error: "it must be a JSON array of servers." };
  const servers: IceServer[] = [];
  for (const [i, entry] of data.entries()) {
    const e = entry as { urls?: unknown; username?: unknown; credential?: unknown };
    const urls = typeof e?.urls === "string" ? [e.urls] : e?.urls;
    if (!Array.isArray(urls) || !urls.length || !urls.every((u) => typeof u === "string" && SCHEME.test(u)))
      return { error: `server ${i + 1} needs "urls": one or more stun: or turn: addresses.` };
    if (urls.some((u) => u.startsWith("turn")) && (typeof e.username !== "string" || typeof e.credential !== "string"))
      return { error: `server ${i + 1} is a TURN server: give it a "username" and a "credential".` };
    servers.push({
      urls,
      ...(typeof e.username === "string" ? { username: e.username } : {}),
      ...(typeof e.credential === "string" ? { credential: e.credential } : {}),
    });
  }
  return { servers };
}
