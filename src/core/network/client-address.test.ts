import { describe, expect, it } from "vitest";
import { clientAddress, parseTrustedProxies } from "./client-address";
import { formatIp, inRange, parseIp, parseRange } from "./ip";

const ranges = (setting: string) => {
  const parsed = parseTrustedProxies(setting);
  if ("error" in parsed) throw new Error(parsed.error);
  return parsed.ranges;
};

describe("IP addresses", () => {
  it.each<[string, string | null]>([
    ["192.0.2.1", "192.0.2.1"],
    ["::ffff:192.0.2.1", "192.0.2.1"],
    ["::FFFF:c000:0201", "192.0.2.1"],
    ["[2001:db8::1]", "2001:db8:0:0:0:0:0:1"],
    ["fe80::1%eth0", "fe80:0:0:0:0:0:0:1"],
    ["::1", "0:0:0:0:0:0:0:1"],
    ["::", "0:0:0:0:0:0:0:0"],
    ["2001:DB8:0:0:0:0:0:1", "2001:db8:0:0:0:0:0:1"],
    ["256.0.0.1", null],
    ["1.2.3", null],
    ["01234.1.1.1", null],
    ["1::2::3", null],
    ["1:2:3:4:5:6:7:8:9", null],
    ["1:2:3:4:5:6:7:8::", null],
    ["::fffff", null],
    ["unknown", null],
    ["", null],
  ])("%s reads as %s", (text, expected) => {
    const ip = parseIp(text);
    expect(ip && formatIp(ip)).toBe(expected);
  });

  it.each<[string, string, boolean]>([
    ["10.1.2.3", "10.0.0.0/8", true],
    ["11.1.2.3", "10.0.0.0/8", false],
    ["192.168.1.130", "192.168.1.128/25", true],
    ["192.168.1.127", "192.168.1.128/25", false],
    ["::ffff:10.9.9.9", "10.0.0.0/8", true],
    ["10.9.9.9", "::ffff:10.0.0.0/104", true],
    ["203.0.113.5", "0.0.0.0/0", true],
    ["2001:db8::5", "2001:db8::/32", true],
    ["2001:db9::5", "2001:db8::/32", false],
    ["2001:db8::5", "0.0.0.0/0", false],
    ["127.0.0.1", "127.0.0.1", true],
    ["127.0.0.2", "127.0.0.1", false],
  ])("%s in %s: %s", (ip, range, expected) => {
    expect(inRange(parseIp(ip)!, parseRange(range)!)).toBe(expected);
  });

  it.each([
    "10.0.0.0/33",
    "10.0.0.0/-1",
    "10.0.0.0/",
    "10.0.0.0/8/8",
    "::ffff:10.0.0.0/95",
    "fd00::/129",
    "proxy.local",
  ])("refuses the range %s", (text) => expect(parseRange(text)).toBeNull());
});

describe("trusted proxies setting", () => {
  it("reads addresses and ranges, ignoring spaces and empty entries", () => {
    expect(ranges(" 127.0.0.1, 10.0.0.0/8,,fd00::/8 ")).toHaveLength(3);
    expect(ranges("")).toEqual([]);
  });

  it("names the entry it cannot read", () => {
    expect(parseTrustedProxies("127.0.0.1, proxy.local")).toEqual({
      error: '"proxy.local" is not an IP address or CIDR range (such as 10.0.0.0/8)',
    });
  });
});

describe("the client's address", () => {
  it.each<[string, string | undefined, string | string[] | undefined, string, string]>([
    // With no trusted proxies X-Forwarded-For is never read.
    ["ignores the header when nothing is trusted", "198.51.100.7", "203.0.113.1", "", "198.51.100.7"],
    ["reports a mapped socket address in IPv4 form", "::ffff:198.51.100.7", undefined, "", "198.51.100.7"],
    [
      "ignores the header from a socket that is not a trusted proxy",
      "198.51.100.7",
      "203.0.113.1",
      "10.0.0.0/8",
      "198.51.100.7",
    ],
    ["takes the entry the trusted proxy appended", "10.0.0.2", "203.0.113.1", "10.0.0.0/8", "203.0.113.1"],
    [
      "takes the right-most untrusted entry, not what the client prepended",
      "10.0.0.2",
      "1.1.1.1, 203.0.113.1",
      "10.0.0.0/8",
      "203.0.113.1",
    ],
    [
      "walks past a chain of trusted proxies",
      "10.0.0.2",
      "1.1.1.1, 203.0.113.1, 10.0.0.9, 10.0.0.5",
      "10.0.0.0/8",
      "203.0.113.1",
    ],
    [
      "reads several X-Forwarded-For headers as one list",
      "10.0.0.2",
      ["1.1.1.1", "203.0.113.1, 10.0.0.9"],
      "10.0.0.0/8",
      "203.0.113.1",
    ],
    [
      "matches a mapped socket address against an IPv4 range",
      "::ffff:10.0.0.2",
      "203.0.113.1",
      "10.0.0.0/8",
      "203.0.113.1",
    ],
    ["answers with the proxy when the header is missing", "10.0.0.2", undefined, "10.0.0.0/8", "10.0.0.2"],
    ["answers with the left-most proxy when every hop is trusted", "10.0.0.2", "10.0.0.7", "10.0.0.0/8", "10.0.0.7"],
    [
      "stops at an unreadable entry and answers with the nearest proxy",
      "10.0.0.2",
      "203.0.113.1, bogus, 10.0.0.9",
      "10.0.0.0/8",
      "10.0.0.9",
    ],
    ["handles IPv6 clients behind the proxy", "10.0.0.2", "2001:db8::7", "10.0.0.0/8", "2001:db8:0:0:0:0:0:7"],
    ["answers unknown when the socket is gone", undefined, "203.0.113.1", "0.0.0.0/0", "unknown"],
  ])("%s", (_name, socketAddress, forwardedFor, trusted, expected) => {
    expect(clientAddress({ socketAddress, forwardedFor, trustedProxies: ranges(trusted) })).toBe(expected);
  });
});
