// The trial runtime's WebSocket server (Bun). Every message is parsed against
// the protocol file and checked by the access policy before it does anything.
import { studyRoleMay } from "@/core/access/policy";
import type { Database } from "@/server/db/client";
import { verifySocketToken, type SocketClaims } from "@/server/trials/socket-token";
import { eventsSince, type StoredEvent } from "@/server/trials/event-store";
import { parseClientMessage, SOCKET_PROTOCOL_VERSION, type ServerMessage, type Viewer } from "./protocol";
import { annotate } from "./annotations";
import type { EventRelay } from "./relay";
import type { TrialHosts } from "./trial-hosts";

interface Connection {
  claims: SocketClaims | null;
  unsubscribe?: () => void;
}

type Socket = { data: Connection; send(text: string): unknown; close(code?: number, reason?: string): void };

export interface RuntimeOptions {
  db: Database;
  hosts: TrialHosts;
  relay: EventRelay;
  secret: string;
  hostname: string;
  port: number;
}

// Every client of a trial gets the same batch: serialise it once, not once per client.
const serialised = new WeakMap<StoredEvent[], string>();
function eventsMessage(events: StoredEvent[]): string {
  let text = serialised.get(events);
  if (text === undefined) serialised.set(events, (text = JSON.stringify({ type: "events", events } satisfies ServerMessage)));
  return text;
}

export function startRuntimeServer({ db, hosts, relay, secret, hostname, port }: RuntimeOptions) {
  const viewers = new Map<string, Set<Socket>>();
  const send = (ws: Socket, message: ServerMessage): void => void ws.send(JSON.stringify(message));
  const presence = (trialId: string) => {
    const sockets = [...(viewers.get(trialId) ?? [])];
    const list: Viewer[] = sockets.map((s) => ({ userId: s.data.claims!.userId, name: s.data.claims!.name, role: s.data.claims!.studyRole }));
    for (const s of sockets) send(s, { type: "presence", viewers: list });
    return list;
  };

  async function hello(ws: Socket, token: string, lastSeq: number): Promise<void> {
    const claims = verifySocketToken(token, secret);
    if (!claims) return ws.close(4401, "Your link to this trial has expired. Reload the page.");
    ws.data.claims = claims;
    const host = await hosts.get(claims.trialId);
    const missed: StoredEvent[] = await eventsSince(db, claims.trialId, lastSeq);
    const push = (events: StoredEvent[]) => ws.send(eventsMessage(events));
    // Owned here: straight from the host. Owned by another process: through the relay.
    ws.data.unsubscribe = host ? host.subscribe(push) : relay.follow(claims.trialId, missed.at(-1)?.seq ?? lastSeq, push);
    const set = viewers.get(claims.trialId) ?? new Set();
    viewers.set(claims.trialId, set.add(ws));
    send(ws, { type: "welcome", version: SOCKET_PROTOCOL_VERSION, trialId: claims.trialId, role: claims.studyRole, events: missed, viewers: presence(claims.trialId) });
    if (host) send(ws, { type: "robot", connected: host.robotStatus() });
  }

  /** Tells everyone in a trial at once when its robot drops or comes back. */
  const announceRobot = (trialId: string, connected: boolean, detail?: string) => {
    for (const s of viewers.get(trialId) ?? []) send(s, { type: "robot", connected, ...(detail ? { detail } : {}) });
  };

  async function onMessage(ws: Socket, text: string): Promise<void> {
    const parsed = parseClientMessage(text);
    if (!parsed.ok) return send(ws, { type: "rejected", requestId: null, reason: parsed.reason });
    const message = parsed.message;
    if (message.type === "ping") return send(ws, { type: "pong" });
    if (message.type === "hello") return hello(ws, message.token, message.lastSeq);
    const claims = ws.data.claims;
    if (!claims) return send(ws, { type: "rejected", requestId: message.requestId, reason: "Say hello with your trial link first." });
    const op = message.type === "command" ? "trial.run" : "annotation.create";
    if (!studyRoleMay(claims.studyRole, op)) {
      return send(ws, { type: "rejected", requestId: message.requestId, reason: `As ${claims.studyRole} you may watch this trial but not run it.` });
    }
    if (message.type === "annotate") {
      const annotation = await annotate(db, claims, message.label, message.note);
      for (const s of viewers.get(claims.trialId) ?? []) send(s, { type: "annotation", annotation });
      return send(ws, { type: "ack", requestId: message.requestId, seqs: [] });
    }
    const host = await hosts.get(claims.trialId);
    if (!host) {
      return send(ws, { type: "rejected", requestId: message.requestId, reason: "Another runtime process is running this trial; reload the page to reach it." });
    }
    const command = message.command.kind === "unscripted" ? { ...message.command, actionId: crypto.randomUUID() } : message.command;
    const result = await host.command(command, claims.userId);
    if (result.ok) send(ws, { type: "ack", requestId: message.requestId, seqs: result.events.map((e) => e.seq) });
    else send(ws, { type: "rejected", requestId: message.requestId, reason: result.reason });
  }

  const server = Bun.serve<Connection>({
    hostname,
    port,
    fetch(req, server) {
      if (server.upgrade(req, { data: { claims: null } })) return undefined;
      return new Response("This is the HRIStudio trial runtime: connect with a WebSocket.", { status: 426 });
    },
    websocket: {
      async message(ws, raw): Promise<void> {
        const text = typeof raw === "string" ? raw : new TextDecoder().decode(raw);
        try {
          await onMessage(ws, text);
        } catch (error) {
          // One failed message must never take the trial down for everyone else.
          console.error(`[runtime] ${error instanceof Error ? error.message : String(error)}`);
          const requestId = (JSON.parse(text) as { requestId?: string }).requestId ?? null;
          send(ws, { type: "rejected", requestId, reason: "The server could not store that; nothing was changed. Try again." });
        }
      },
      close(ws) {
        ws.data.unsubscribe?.();
        const trialId = ws.data.claims?.trialId;
        if (trialId && viewers.get(trialId)?.delete(ws)) presence(trialId);
      },
    },
  });
  return { server, announceRobot };
}
