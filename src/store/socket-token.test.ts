import { createHmac } from "node:crypto";
import { describe, expect, it } from "vitest";
import { signSocketToken, TOKEN_LIFETIME_MS, verifySocketToken } from "./socket-token";

const secret = "s".repeat(32);
const who = { userId: "u1", trialId: "t1" };
const reclaim = (t: string, change: Record<string, unknown>) => {
  const [body, mac] = t.split(".");
  const claims = JSON.parse(Buffer.from(body!, "base64url").toString("utf8"));
  return `${Buffer.from(JSON.stringify({ ...claims, ...change })).toString("base64url")}.${mac}`;
};

describe("socket tokens", () => {
  it.each<[string, (t: string) => string, number, boolean]>([
    ["a fresh token is accepted", (t) => t, 0, true],
    ["an expired token is refused", (t) => t, TOKEN_LIFETIME_MS + 1, false],
    ["a token moved to another trial is refused", (t) => reclaim(t, { trialId: "t2" }), 0, false],
    ["a token moved to another user is refused", (t) => reclaim(t, { userId: "u2" }), 0, false],
    ["a token with a longer life is refused", (t) => reclaim(t, { exp: Date.now() + 9e9 }), 0, false],
    ["a token signed with another secret is refused", () => signSocketToken(who, "x".repeat(32)), 0, false],
    [
      "a token signed with the auth secret itself is refused",
      (t) => `${t.split(".")[0]}.${createHmac("sha256", secret).update(t.split(".")[0]!).digest("base64url")}`,
      0,
      false,
    ],
    ["garbage is refused", () => "not-a-token", 0, false],
  ])("%s", (_name, tamper, later, accepted) => {
    const now = 1_000_000;
    const token = tamper(signSocketToken(who, secret, now));
    expect(verifySocketToken(token, secret, now + later) !== null).toBe(accepted);
  });

  it("carries who and which trial, a fresh id each time, and no role", () => {
    const a = verifySocketToken(signSocketToken(who, secret), secret)!;
    const b = verifySocketToken(signSocketToken(who, secret), secret)!;
    expect(a).toMatchObject(who);
    expect(a.tokenId).not.toBe(b.tokenId);
    expect(Object.keys(a).sort()).toEqual(["exp", "tokenId", "trialId", "userId"]);
  });
});
