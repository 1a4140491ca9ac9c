import { describe, expect, it } from "vitest";
import { beforeHelloRefusal, HELLO_FRAME_BYTES, LARGEST_FRAME_BYTES, MESSAGE_BYTES, sizeRefusal } from "./limits";
import { SOCKET_MESSAGES_VERSION } from "./messages";

describe("the trial socket's limits", () => {
  it.each<[string, number, string | null]>([
    ["a hello", 300, null],
    ["a hello with the longest token the messages allow", HELLO_FRAME_BYTES, null],
    [
      "a frame one byte past a hello",
      HELLO_FRAME_BYTES + 1,
      "The first message must be a hello of a few hundred bytes; this one had 9 KB, so the connection was closed.",
    ],
    [
      "15 MB",
      15 * 1024 * 1024,
      "The first message must be a hello of a few hundred bytes; this one had 15.0 MB, so the connection was closed.",
    ],
  ])("before hello: %s", (_name, bytes, refusal) => {
    expect(beforeHelloRefusal(bytes)).toBe(refusal);
  });

  it.each<[string, Parameters<typeof sizeRefusal>[0], number, string | null]>([
    ["a command of its size", "command", MESSAGE_BYTES.command, null],
    [
      "a command past its size",
      "command",
      100 * 1024,
      "That command message is too large (100 KB; at most 64 KB): nothing was done.",
    ],
    ["a ping of a few bytes", "ping", 15, null],
    ["a ping padded out", "ping", 2000, "That ping message is too large (2 KB; at most 1 KB): nothing was done."],
    ["a signal with a long session description", "signal", 200 * 1024, null],
    [
      "a camera message padded out",
      "camera",
      4096,
      "That camera message is too large (4 KB; at most 1 KB): nothing was done.",
    ],
  ])("after hello: %s", (_name, type, bytes, refusal) => {
    expect(sizeRefusal(type, bytes)).toBe(refusal);
  });

  it("fits the longest hello the messages allow, and reads no frame larger than its largest kind", () => {
    const hello = JSON.stringify({
      type: "hello",
      version: SOCKET_MESSAGES_VERSION,
      token: "t".repeat(4000),
      lastSeq: 2 ** 31 - 1,
    });
    expect(beforeHelloRefusal(Buffer.byteLength(hello))).toBeNull();
    expect(LARGEST_FRAME_BYTES).toBe(MESSAGE_BYTES.signal);
  });
});
