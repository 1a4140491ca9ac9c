import { describe, expect, it } from "vitest";
import { bearerSecret, tokenState } from "./access-token";
import { hashTokenSecret, newTokenSecret } from "./token-secret";
import { decide, type Operation, STUDY_OPERATIONS, SYSTEM_OPERATIONS } from "./policy";

describe("a token's secret", () => {
  it("is our prefix and 256 random bits, stored as its SHA-256", () => {
    const secret = newTokenSecret(new Uint8Array(32).fill(255));
    expect(secret).toBe(`hri_${"_".repeat(42)}8`);
    expect(newTokenSecret()).toMatch(/^hri_[A-Za-z0-9_-]{43}$/);
    expect(newTokenSecret()).not.toBe(newTokenSecret());
    // FIPS 180-2's example: SHA-256 of "abc".
    expect(hashTokenSecret("abc")).toBe("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  });

  it.each([
    ["Bearer hri_abc", "hri_abc"],
    ["bearer   hri_abc  ", "hri_abc"],
    ["Bearer abc", null],
    ["Basic hri_abc", null],
    ["Bearer hri_a hri_b", null],
    ["", null],
    [null, null],
  ])("Authorization %j → %j", (header, secret) => {
    expect(bearerSecret(header)).toBe(secret);
  });
});

describe("a token's state", () => {
  const now = new Date("2026-05-01T12:00:00Z");
  it.each([
    ["active before its expiry", { expiresAt: new Date("2026-05-01T12:00:01Z"), revokedAt: null }, "active"],
    ["expired at its expiry", { expiresAt: now, revokedAt: null }, "expired"],
    [
      "revoked, even if also expired",
      { expiresAt: new Date("2026-01-01"), revokedAt: new Date("2025-12-01") },
      "revoked",
    ],
  ])("%s", (_, token, state) => {
    expect(tokenState(token, now)).toBe(state);
  });
});

describe("what the policy lets a token do", () => {
  const every = [...Object.keys(SYSTEM_OPERATIONS), ...Object.keys(STUDY_OPERATIONS)] as Operation[];
  it.each(every)("%s", (op) => {
    const decision = decide({ systemRole: "administrator", studyRole: "owner", viaToken: true }, op);
    // Reading only: the studies, their data, and a trial's recording (a token read it with the data before it had an operation of its own).
    expect(decision.allow).toBe(["data.read", "data.studies", "recording.read"].includes(op));
  });

  it("still applies the owner's study role and blinds", () => {
    expect(decide({ systemRole: "wizard", studyRole: "wizard", viaToken: true }, "data.read").allow).toBe(false);
    expect(decide({ systemRole: "researcher", studyRole: null, viaToken: true }, "data.read")).toMatchObject({
      allow: false,
      hidden: true,
    });
    const blinded = { conditionsHidden: false, resultsHidden: true };
    expect(
      decide({ systemRole: "observer", studyRole: "observer", blinding: blinded, viaToken: true }, "data.read"),
    ).toMatchObject({
      allow: false,
      hidden: false,
    });
  });
});
