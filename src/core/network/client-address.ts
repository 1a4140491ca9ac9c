// Who is on the other end of a request. The socket's address is the only fact;
// X-Forwarded-For is a claim anyone can write. It is believed only as far as
// it was appended by proxies the administrator listed (HRI_TRUSTED_PROXIES):
// walking from the right, each trusted hop vouches for the entry before it,
// and the first hop that is not trusted is the client.
import { formatIp, inRange, parseIp, parseRange, type IpRange } from "./ip";

/** Set by the web server on every request, after deleting whatever the client sent. */
export const CLIENT_ADDRESS_HEADER = "x-hri-client-address";

/** Parses the comma-separated setting; names the first entry that is not an address or range. */
export function parseTrustedProxies(setting: string): { ranges: IpRange[] } | { error: string } {
  const entries = setting
    .split(",")
    .map((e) => e.trim())
    .filter(Boolean);
  const ranges: IpRange[] = [];
  for (const entry of entries) {
    const range = parseRange(entry);
    if (!range) return { error: `"${entry}" is not an IP address or CIDR range (such as 10.0.0.0/8)` };
    ranges.push(range);
  }
  return { ranges };
}

export interface Hop {
  /** The socket's remote address; undefined when the socket is already gone. */
  socketAddress: string | undefined;
  /** The X-Forwarded-For header(s) as received. */
  forwardedFor: string | string[] | undefined;
  trustedProxies: IpRange[];
}

export function clientAddress({ socketAddress, forwardedFor, trustedProxies }: Hop): string {
  const socket = socketAddress === undefined ? null : parseIp(socketAddress);
  if (!socket) return "unknown";
  const trusted = (ip: Uint8Array) => trustedProxies.some((range) => inRange(ip, range));
  if (!trusted(socket)) return formatIp(socket);
  const claims = [forwardedFor ?? []]
    .flat()
    .join(",")
    .split(",")
    .map((e) => e.trim())
    .filter(Boolean);
  let nearest = socket;
  for (let i = claims.length - 1; i >= 0; i--) {
    const hop = parseIp(claims[i]!);
    // A trusted proxy wrote something that is not an address: the proxy itself
    // is the most we know, never an entry further left that a client could write.
    if (!hop) return formatIp(nearest);
    if (!trusted(hop)) return formatIp(hop);
    nearest = hop;
  }
  // Every hop is a trusted proxy (a request from the proxy's own host).
  return formatIp(nearest);
}
