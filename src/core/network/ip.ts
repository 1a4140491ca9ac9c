// IP addresses and CIDR ranges as bytes, without node:net so the core stays
// pure. An IPv4-mapped IPv6 address (::ffff:192.0.2.1, what a dual-stack
// socket reports for an IPv4 client) is the same client as its IPv4 form, so
// it parses to the same four bytes.

export type IpBytes = Uint8Array;

export interface IpRange {
  bytes: IpBytes;
  prefix: number;
}

function parseIpv4(text: string): IpBytes | null {
  const parts = text.split(".");
  if (parts.length !== 4 || !parts.every((p) => /^\d{1,3}$/.test(p) && Number(p) <= 255)) return null;
  return Uint8Array.from(parts.map(Number));
}

function parseIpv6(text: string): IpBytes | null {
  const halves = text.split("::");
  if (halves.length > 2) return null;
  const groupsOf = (half: string) => (half === "" ? [] : half.split(":"));
  const head = groupsOf(halves[0]!);
  const tail = halves.length === 2 ? groupsOf(halves[1]!) : [];
  // A trailing dotted quad stands for the last two groups.
  const last = (tail.length ? tail : head).at(-1);
  let v4: IpBytes | null = null;
  if (last?.includes(".")) {
    v4 = parseIpv4(last);
    if (!v4) return null;
    (tail.length ? tail : head).pop();
  }
  const wanted = v4 ? 6 : 8;
  const given = head.length + tail.length;
  if (halves.length === 2 ? given >= wanted : given !== wanted) return null;
  const groups = [...head, ...Array<string>(wanted - given).fill("0"), ...tail];
  if (!groups.every((g) => /^[0-9a-f]{1,4}$/i.test(g))) return null;
  const bytes = new Uint8Array(16);
  groups.forEach((g, i) => {
    const n = parseInt(g, 16);
    bytes[i * 2] = n >> 8;
    bytes[i * 2 + 1] = n & 0xff;
  });
  if (v4) bytes.set(v4, 12);
  const mapped = bytes.subarray(0, 10).every((b) => b === 0) && bytes[10] === 0xff && bytes[11] === 0xff;
  return mapped ? bytes.slice(12) : bytes;
}

/** The address's bytes (4 for IPv4 and IPv4-mapped IPv6, 16 for IPv6), or null if it is not an address. */
export function parseIp(text: string): IpBytes | null {
  const bare = text
    .trim()
    .replace(/^\[(.*)\]$/, "$1")
    .replace(/%.*$/, "");
  return bare.includes(":") ? parseIpv6(bare) : parseIpv4(bare);
}

/** "10.0.0.0/8", "fd00::/8" or a single address (a range of one). */
export function parseRange(text: string): IpRange | null {
  const [address, prefixText, ...rest] = text.trim().split("/");
  const bytes = parseIp(address!);
  if (!bytes || rest.length) return null;
  // An IPv4-mapped range such as ::ffff:10.0.0.0/104 is the IPv4 range /8.
  const offset = bytes.length === 4 && address!.includes(":") ? 96 : 0;
  const prefix =
    prefixText === undefined ? bytes.length * 8 : /^\d{1,3}$/.test(prefixText) ? Number(prefixText) - offset : NaN;
  return Number.isInteger(prefix) && prefix >= 0 && prefix <= bytes.length * 8 ? { bytes, prefix } : null;
}

export function inRange(ip: IpBytes, range: IpRange): boolean {
  if (ip.length !== range.bytes.length) return false;
  for (let bit = 0; bit < range.prefix; bit += 8) {
    const take = Math.min(8, range.prefix - bit);
    const mask = (0xff << (8 - take)) & 0xff;
    if ((ip[bit / 8]! & mask) !== (range.bytes[bit / 8]! & mask)) return false;
  }
  return true;
}

/** One spelling per address: dotted IPv4, or eight lower-case hex groups. */
export function formatIp(ip: IpBytes): string {
  if (ip.length === 4) return ip.join(".");
  const groups: string[] = [];
  for (let i = 0; i < 16; i += 2) groups.push(((ip[i]! << 8) | ip[i + 1]!).toString(16));
  return groups.join(":");
}
