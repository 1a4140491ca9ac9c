import { describe, expect, it } from "vitest";
import { signSocketToken, TOKEN_LIFETIME_MS, verifySocketToken } from "./socket-token";

const secret = "s".repeat(32);
const claims = { userId: "u1", name: "Wim", trialId: "t1", studyRole: "wizard" as const };

describe("socket tokens", () => {
  it.each<[string, (t: string) => string, number, boolean]>([
    ["a fresh token is accepted", (t) => t, 0, true],
    ["an expired token is refused", (t) => t, TOKEN_LIFETIME_MS + 1, false],
    ["a token with changed claims is refused", (t) => Buffer.from(JSON.stringify({ ...claims, studyRole: "owner", exp: Date.now() + 9e9 })).toString("base64url") + "." + t.split(".")[1], 0, false],
    ["a token signed with another secret is refused", () => signSocketToken(claims, "x".repeat(32)), 0, false],
    ["garbage is refused", () => "not-a-token", 0, false],
  ])("%s", (_name, tamper, later, accepted) => {
    const now = 1_000_000;
    const token = tamper(signSocketToken(claims, secret, now));
    expect(verifySocketToken(token, secret, now + later) !== null).toBe(accepted);
  });
});
