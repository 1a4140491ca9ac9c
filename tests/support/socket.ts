// A trial-runtime client for tests: a real WebSocket speaking the socket
// protocol, checking every message the runtime sends as the browser does.
import WebSocket from "ws";
import { parseServerMessage, SOCKET_MESSAGES_VERSION, type ServerMessage } from "../../src/core/socket/messages";
import { welcomeJoiner } from "../../src/core/socket/welcome";

export interface TrialSocket {
  messages: Array<Record<string, unknown>>;
  /** Set when the server closed the connection. */
  closed: { code: number; reason: string } | null;
  send(message: Record<string, unknown>): void;
  /** Resolves with the first message (already received or future) that matches. */
  next(match: (m: Record<string, unknown>) => boolean, timeoutMs?: number): Promise<Record<string, unknown>>;
  command(requestId: string, command: Record<string, unknown>): Promise<Record<string, unknown>>;
  /** Calls `listen` with every message from now on, as the page's own handlers see them. */
  listen(listen: (m: ServerMessage) => void): void;
  close(): void;
}

/** `sentWithHello`: messages sent right behind the hello, before its welcome, as a page may. */
export async function connectTrial(
  url: string,
  token: string,
  lastSeq = 0,
  sentWithHello: Array<Record<string, unknown>> = [],
): Promise<TrialSocket> {
  const ws = new WebSocket(url);
  const messages: Array<Record<string, unknown>> = [];
  const waiters = new Set<() => void>();
  const listeners = new Set<(m: ServerMessage) => void>();
  const join = welcomeJoiner();
  ws.on("message", (data) => {
    const parsed = parseServerMessage(String(data));
    // Thrown here, it fails the test that received it as an unhandled error.
    if (!parsed.ok)
      throw new Error(`The runtime sent a message the browser would refuse: ${parsed.reason}\n${String(data)}`);
    // As the page does: a welcome's parts held, and joined into it.
    const joined = join(parsed.message);
    if (!joined.ok) throw new Error(`The runtime's welcome did not join: ${joined.reason}`);
    if (!joined.message) return;
    messages.push(joined.message);
    for (const listen of listeners) listen(joined.message);
    for (const w of [...waiters]) w();
  });
  await new Promise<void>((ok, fail) => {
    ws.once("open", () => ok());
    ws.once("error", fail);
  });
  const socket: TrialSocket = {
    messages,
    closed: null,
    send: (message) => ws.send(JSON.stringify(message)),
    next(match, timeoutMs = 10_000) {
      return new Promise((ok, fail) => {
        const check = () => {
          const found = messages.find(match);
          if (found) {
            waiters.delete(check);
            clearTimeout(timer);
            ok(found);
          }
        };
        const timer = setTimeout(() => {
          waiters.delete(check);
          fail(new Error(`No matching message; got ${JSON.stringify(messages).slice(-600)}`));
        }, timeoutMs);
        waiters.add(check);
        check();
      });
    },
    command(requestId, command) {
      socket.send({ type: "command", requestId, command });
      // The outcome: "ack" or "rejected" (a stop's "halted" comes before it and is not one).
      return socket.next((m) => m.requestId === requestId && (m.type === "ack" || m.type === "rejected"));
    },
    listen: (listen) => void listeners.add(listen),
    close: () => ws.close(),
  };
  const closed = new Promise<void>((ok) =>
    ws.once("close", (code, reason) => {
      socket.closed = { code, reason: String(reason) };
      ok();
    }),
  );
  socket.send({ type: "hello", version: SOCKET_MESSAGES_VERSION, token, lastSeq });
  for (const message of sentWithHello) socket.send(message);
  await Promise.race([socket.next((m) => m.type === "welcome" || m.type === "rejected"), closed]);
  return socket;
}
