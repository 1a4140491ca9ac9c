import { describe, expect, it } from "vitest";
import { linkProblem } from "./link-problem";

const error = (message: string, fields: Record<string, unknown> = {}) => Object.assign(new Error(message), fields);

describe("why a robot could not be reached, in plain words", () => {
  it.each<[string, unknown, string]>([
    [
      "a name DNS does not know",
      error("getaddrinfo ENOTFOUND nao.invalid", { code: "ENOTFOUND", hostname: "nao.invalid" }),
      'no host named "nao.invalid" was found',
    ],
    ["DNS unsure", error("getaddrinfo EAI_AGAIN nao", { code: "EAI_AGAIN" }), "no host of that name was found"],
    [
      "a closed port",
      error("connect ECONNREFUSED 127.0.0.1:1", { code: "ECONNREFUSED" }),
      "the connection was refused: nothing answers at that address and port",
    ],
    [
      "a closed port, as Bun's fetch says it",
      error("Unable to connect. Is the computer able to access the url?", { code: "ConnectionRefused" }),
      "the connection was refused: nothing answers at that address and port",
    ],
    [
      "a closed port, as Node's fetch says it",
      new TypeError("fetch failed", { cause: error("connect ECONNREFUSED 127.0.0.1:1", { code: "ECONNREFUSED" }) }),
      "the connection was refused: nothing answers at that address and port",
    ],
    [
      "an unreachable network",
      error("connect ENETUNREACH", { code: "ENETUNREACH" }),
      "that address cannot be reached from this network",
    ],
    [
      "an SSH handshake never answered",
      error("Timed out while waiting for handshake", { level: "client-timeout" }),
      "the robot did not answer in time",
    ],
    [
      "a refused SSH login",
      error("All configured authentication methods failed", { level: "client-authentication" }),
      "the robot refused the login: check the user name and its key or password",
    ],
    [
      "an abort on timeout",
      error("The operation timed out.", { name: "TimeoutError" }),
      "the robot did not answer in time",
    ],
    ["a cut connection", error("read ECONNRESET", { code: "ECONNRESET" }), "the robot's side cut the connection"],
    [
      "a port out of range",
      error("Port should be >= 0 and < 65536. Received 70000.", { code: "ERR_SOCKET_BAD_PORT" }),
      "the port is not a port number (1–65535)",
    ],
    ["ws's opening handshake unanswered", error("Opening handshake has timed out"), "the robot did not answer in time"],
    [
      "a WebSocket upgrade refused",
      error("Unexpected server response: 403"),
      "the robot's side refused the connection (HTTP 403)",
    ],
    ["ws's invalid URL", new SyntaxError("Invalid URL: not a url"), "the address is not a URL"],
    ["anything else: its first line, without its class", error("Error: the bridge\n    at x (y.js:1:1)"), "the bridge"],
    ["not an error at all", "gone", "gone"],
  ])("%s", (_name, thrown, reason) => {
    expect(linkProblem(thrown)).toBe(reason);
  });
});
