// The simulated robot's host key: ssh2's ed25519 generator writes about one
// key in 200 that ssh2 then refuses (a 31-byte public key); the simulator's
// own must always be readable, or the robot fails to start now and again.
import { utils } from "ssh2";
import { describe, expect, it } from "vitest";
import { hostKey } from "./ssh";

describe("the simulated robot's host key", () => {
  it("is one ssh2 reads, every time (2,000 made)", () => {
    const unreadable = Array.from({ length: 2000 }, hostKey).filter((key) => utils.parseKey(key) instanceof Error);
    expect(unreadable).toEqual([]);
  });
});
