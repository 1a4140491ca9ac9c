import { describe, expect, it } from "vitest";
import { parseClientMessage, SOCKET_PROTOCOL_VERSION } from "./messages";

describe("the socket protocol", () => {
  it.each<[string, string, string | null]>([
    ["a hello", JSON.stringify({ type: "hello", version: SOCKET_PROTOCOL_VERSION, token: "t", lastSeq: 0 }), null],
    ["a command", JSON.stringify({ type: "command", requestId: "r1", command: { kind: "answer", actionId: "a", optionId: "o" } }), null],
    ["not JSON", "{nope", "The message is not valid JSON."],
    ["an unknown type", JSON.stringify({ type: "shout" }), "The message is not understood: type: "],
    ["an old protocol version", JSON.stringify({ type: "hello", version: SOCKET_PROTOCOL_VERSION - 1, token: "t", lastSeq: 0 }), "The message is not understood: version: "],
    ["a command missing a field", JSON.stringify({ type: "command", requestId: "r1", command: { kind: "trigger" } }), "The message is not understood: command.actionId: "],
    ["a negative lastSeq", JSON.stringify({ type: "hello", version: SOCKET_PROTOCOL_VERSION, token: "t", lastSeq: -1 }), "The message is not understood: lastSeq: "],
  ])("%s", (_name, raw, reasonStart) => {
    const parsed = parseClientMessage(raw);
    if (reasonStart === null) expect(parsed.ok).toBe(true);
    else expect(!parsed.ok && parsed.reason.startsWith(reasonStart)).toBe(true);
  });
});
