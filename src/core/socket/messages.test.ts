import { describe, expect, it } from "vitest";
import type { StoredEvent } from "@/core/trial";
import { parseClientMessage, parseServerMessage, SOCKET_MESSAGES_VERSION, toWire } from "./messages";

describe("the socket messages", () => {
  it.each<[string, string, string | null]>([
    ["a hello", JSON.stringify({ type: "hello", version: SOCKET_MESSAGES_VERSION, token: "t", lastSeq: 0 }), null],
    [
      "a command",
      JSON.stringify({ type: "command", requestId: "r1", command: { kind: "answer", actionId: "a", optionId: "o" } }),
      null,
    ],
    [
      "a command with the moment the wizard asked, on the page's clock",
      JSON.stringify({ type: "command", requestId: "r1", command: { kind: "next" }, at: 1_795_750_000_000 }),
      null,
    ],
    [
      "a command whose moment is not a number",
      JSON.stringify({ type: "command", requestId: "r1", command: { kind: "next" }, at: "now" }),
      "The message is not understood: at: ",
    ],
    [
      "a video signal from another connection",
      JSON.stringify({
        type: "signal",
        requestId: "r1",
        peerId: "p2",
        signal: {
          kind: "candidate",
          candidate: { candidate: "candidate:1 1 udp 1 10.0.0.2 5000 typ host", sdpMid: "0" },
        },
      }),
      null,
    ],
    [
      "a video signal of another kind",
      JSON.stringify({ type: "signal", requestId: "r1", peerId: "p2", signal: { kind: "shout" } }),
      "The message is not understood: signal.kind: ",
    ],
    ["a page that hides the robot's camera", JSON.stringify({ type: "camera", requestId: "r1", watch: false }), null],
    [
      "a camera message that does not say whether",
      JSON.stringify({ type: "camera", requestId: "r1", watch: "no" }),
      "The message is not understood: watch: ",
    ],
    ["not JSON", "{nope", "The message is not valid JSON."],
    ["an unknown type", JSON.stringify({ type: "shout" }), "The message is not understood: type: "],
    [
      "an old socket messages version",
      JSON.stringify({ type: "hello", version: SOCKET_MESSAGES_VERSION - 1, token: "t", lastSeq: 0 }),
      "The message is not understood: version: ",
    ],
    [
      "a command missing a field",
      JSON.stringify({ type: "command", requestId: "r1", command: { kind: "trigger" } }),
      "The message is not understood: command.actionId: ",
    ],
    [
      "a negative lastSeq",
      JSON.stringify({ type: "hello", version: SOCKET_MESSAGES_VERSION, token: "t", lastSeq: -1 }),
      "The message is not understood: lastSeq: ",
    ],
    [
      "a lastSeq past any stored sequence number",
      JSON.stringify({ type: "hello", version: SOCKET_MESSAGES_VERSION, token: "t", lastSeq: 2 ** 31 }),
      "The message is not understood: lastSeq: ",
    ],
    [
      "the largest lastSeq",
      JSON.stringify({ type: "hello", version: SOCKET_MESSAGES_VERSION, token: "t", lastSeq: 2 ** 31 - 1 }),
      null,
    ],
  ])("%s", (_name, raw, reasonStart) => {
    const parsed = parseClientMessage(raw);
    if (reasonStart === null) expect(parsed.ok).toBe(true);
    else expect(!parsed.ok && parsed.reason.startsWith(reasonStart)).toBe(true);
  });
});

const stored: StoredEvent = {
  type: "trial.started",
  seq: 1,
  relMs: 0,
  trialId: "t1",
  serverTime: new Date("2026-01-01T10:00:00.000Z"),
  actorId: "u1",
};
const welcome = (events: unknown[], version: number = SOCKET_MESSAGES_VERSION) =>
  JSON.stringify({
    type: "welcome",
    version,
    trialId: "t1",
    role: "wizard",
    mayRun: true,
    events,
    parts: 0,
    viewers: [],
    peerId: "p1",
    iceServers: [],
  });

describe("the browser's check of what the runtime sends", () => {
  it.each<[string, string, string | null]>([
    ["a welcome with the log", welcome([toWire(stored)]), null],
    ["a batch of events", JSON.stringify({ type: "events", events: [toWire(stored)] }), null],
    ["a part of a welcome", JSON.stringify({ type: "welcome.part", part: 0, events: [toWire(stored)] }), null],
    ["an ack", JSON.stringify({ type: "ack", requestId: "r1", seqs: [2, 3] }), null],
    ["a rejection of no request", JSON.stringify({ type: "rejected", requestId: null, reason: "No." }), null],
    ["the robot's status", JSON.stringify({ type: "robot", connected: false, detail: "unplugged" }), null],
    [
      "a video offer from another connection",
      JSON.stringify({
        type: "signal",
        peerId: "p2",
        signal: { kind: "description", description: { type: "offer", sdp: "v=0" } },
      }),
      null,
    ],
    [
      "a video signal from another connection",
      JSON.stringify({
        type: "signal",
        requestId: "r1",
        peerId: "p2",
        signal: {
          kind: "candidate",
          candidate: { candidate: "candidate:1 1 udp 1 10.0.0.2 5000 typ host", sdpMid: "0" },
        },
      }),
      null,
    ],
    [
      "a video signal of another kind",
      JSON.stringify({ type: "signal", requestId: "r1", peerId: "p2", signal: { kind: "shout" } }),
      "The message is not understood: signal.kind: ",
    ],
    ["not JSON", "{nope", "The message is not valid JSON."],
    ["an unknown type", JSON.stringify({ type: "shout" }), "The message is not understood: type: "],
    [
      "a welcome from another socket messages version",
      welcome([], SOCKET_MESSAGES_VERSION + 1),
      "The message is not understood: version: ",
    ],
    [
      "an event without its place in the log",
      welcome([{ ...toWire(stored), seq: undefined }]),
      "The message is not understood: events.0: ",
    ],
    [
      "an event whose time is not a string",
      JSON.stringify({ type: "events", events: [{ ...toWire(stored), serverTime: 5 }] }),
      "The message is not understood: events.0: ",
    ],
    [
      "an ack without its request",
      JSON.stringify({ type: "ack", seqs: [] }),
      "The message is not understood: requestId: ",
    ],
  ])("%s", (_name, raw, reasonStart) => {
    const parsed = parseServerMessage(raw);
    if (reasonStart === null) expect(parsed.ok).toBe(true);
    else expect(!parsed.ok && parsed.reason.startsWith(reasonStart)).toBe(true);
  });

  it("carries a stored event as the same event with its time as an ISO string", () => {
    const parsed = parseServerMessage(JSON.stringify({ type: "events", events: [toWire(stored)] }));
    expect(parsed).toEqual({
      ok: true,
      message: { type: "events", events: [{ ...stored, serverTime: "2026-01-01T10:00:00.000Z" }] },
    });
  });
});
