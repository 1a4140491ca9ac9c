import { describe, expect, it } from "vitest";
import { toWire, type ServerMessage, type WireEvent } from "./messages";
import { partEnds, welcomeJoiner, WELCOME_PART_BYTES } from "./welcome";

describe("where a welcome's parts end", () => {
  it.each<[string, number[], number, number[]]>([
    ["no events: the welcome alone", [], 1000, [0]],
    ["all within one part: the welcome's own", [100, 100, 100], 1000, [3]],
    // 64 of envelope + 400 + 1 + 400 = 865; a third (+401) would be 1,266.
    ["split where the next would not fit", [400, 400, 400, 400, 400], 1000, [2, 4, 5]],
    ["exactly at the limit stays in", [467, 468], 1000, [2]],
    ["one byte over moves on", [467, 469], 1000, [1, 2]],
    ["an event larger than a part goes alone", [100, 5000, 100], 1000, [1, 2, 3]],
    ["a large event first", [5000, 100], 1000, [1, 2]],
  ])("%s", (_, sizes, limit, ends) => expect(partEnds(sizes, limit)).toEqual(ends));

  it("keeps each part of a 10 MB log within the limit", () => {
    const sizes = Array.from({ length: 100_000 }, (_, i) => 90 + (i % 30));
    const ends = partEnds(sizes);
    let start = 0;
    for (const end of ends) {
      const text = sizes.slice(start, end).reduce((a, b) => a + b, 0) + (end - start - 1) + 64;
      expect(text).toBeLessThanOrEqual(WELCOME_PART_BYTES);
      start = end;
    }
    expect(ends.at(-1)).toBe(sizes.length);
    expect(ends.length).toBeGreaterThan(40);
  });
});

const event = (seq: number): WireEvent =>
  toWire({ type: "trial.started", seq, relMs: 0, trialId: "t1", serverTime: new Date(0), actorId: null });
const part = (n: number, ...seqs: number[]): ServerMessage => ({
  type: "welcome.part",
  part: n,
  events: seqs.map(event),
});
const welcome = (parts: number, ...seqs: number[]): ServerMessage => ({
  type: "welcome",
  version: 6,
  trialId: "t1",
  role: "observer",
  mayRun: false,
  events: seqs.map(event),
  parts,
  viewers: [],
  peerId: "p1",
  iceServers: [],
});
const ack: ServerMessage = { type: "ack", requestId: "r1", seqs: [] };

describe("the client joining a welcome's parts", () => {
  it.each<[string, ServerMessage[], Array<number[] | "held" | "ack" | string>]>([
    ["a welcome of no parts", [welcome(0, 1)], [[1]]],
    ["parts then the welcome, in order", [part(0, 1, 2), part(1, 3), welcome(2, 4)], ["held", "held", [1, 2, 3, 4]]],
    ["other messages pass as they are", [part(0, 1), ack, welcome(1, 2)], ["held", "ack", [1, 2]]],
    ["a part out of order is said", [part(1, 1)], ["Part 1 of the trial's welcome came where part 0 was due."]],
    [
      "a welcome missing parts is said",
      [part(0, 1), welcome(2, 3)],
      ["held", "The trial's welcome came after 1 of its 2 parts."],
    ],
    [
      "a second welcome (a reconnection) starts again",
      [part(0, 1), welcome(1, 2), welcome(0, 7)],
      ["held", [1, 2], [7]],
    ],
  ])("%s", (_, messages, outcomes) => {
    const join = welcomeJoiner();
    const seen = messages.map((m) => {
      const joined = join(m);
      if (!joined.ok) return joined.reason;
      if (joined.message === null) return "held";
      return joined.message.type === "welcome" ? joined.message.events.map((e) => e.seq) : joined.message.type;
    });
    expect(seen).toEqual(outcomes);
  });
});
