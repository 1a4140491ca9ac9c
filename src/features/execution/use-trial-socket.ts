"use client";
// The browser's side of the trial socket: connects with a fresh token (each
// works once, so every reconnection asks for a new one), resumes from the last
// event it saw after any drop, and applies the events to the trial's state
// with the same engine the server uses.
import { useMutation } from "@tanstack/react-query";
import { useCallback, useEffect, useMemo, useRef, useState } from "react";
import { applyAll, type Command, fold, type TrialProtocol, type TrialState } from "@/core/trial";
import { type Refusal, refusalInForce } from "@/core/trial/refusals";
import {
  parseServerMessage,
  SOCKET_MESSAGES_VERSION,
  type ClientMessage,
  type ServerMessage,
  type Viewer,
  type WireEvent,
  type WizardCommand,
} from "@/core/socket/messages";
import { useTRPC } from "@/lib/trpc";

export type Annotation = Extract<ServerMessage, { type: "annotation" }>["annotation"];
/** One of my code events as the runtime confirmed it. */
export type LiveCode = Extract<ServerMessage, { type: "codes" }>["codes"][number];
type Outcome = { ok: true } | { ok: false; reason: string };

export function useTrialSocket(trialId: string, protocol: TrialProtocol) {
  const trpc = useTRPC();
  const tokenFor = useMutation(trpc.trials.socketToken.mutationOptions());
  const [events, setEvents] = useState<WireEvent[]>([]);
  const [viewers, setViewers] = useState<Viewer[]>([]);
  const [annotations, setAnnotations] = useState<Annotation[]>([]);
  // My own codes as the runtime wrote them this visit (the page merges them with those loaded before).
  const [codes, setCodes] = useState<LiveCode[]>([]);
  const [connected, setConnected] = useState(false);
  const [robot, setRobot] = useState<{ connected: boolean; detail?: string } | null>(null);
  // About the connection (lost, shut out, another version): stays until the connection changes.
  const [notice, setNotice] = useState<string | null>(null);
  // About the trial (a command refused): stays only while the trial is as it was when refused.
  const [refusal, setRefusal] = useState<Refusal | null>(null);
  // A stop that reached the robot but is not logged yet, a second after: the page says the log is behind.
  const [logBehind, setLogBehind] = useState<string | null>(null);
  // Whether the server lets me command this trial (role, assigned wizard), as it last said.
  const [mayRun, setMayRun] = useState<boolean | null>(null);
  const socket = useRef<WebSocket | null>(null);
  const lastSeq = useRef(0);
  const pending = useRef(new Map<string, (o: Outcome) => void>());
  // The command each request carries, so that a refusal can be checked against the trial as it moves on.
  const sent = useRef(new Map<string, Command>());

  const receive = useCallback((incoming: WireEvent[]) => {
    const fresh = incoming.filter((e) => e.seq > lastSeq.current);
    if (!fresh.length) return;
    lastSeq.current = fresh.at(-1)!.seq;
    setEvents((before) => [...before, ...fresh]);
  }, []);

  // One connection per trial: `receive` is stable, and the token mutation's object changes on every render.
  // biome-ignore lint/correctness/useExhaustiveDependencies: see above
  useEffect(() => {
    let stopped = false;
    let retry = 500;
    const connect = async () => {
      let ticket: { url: string; token: string };
      try {
        ticket = await tokenFor.mutateAsync({ trialId });
      } catch {
        if (!stopped) setTimeout(connect, retry);
        return;
      }
      const ws = new WebSocket(ticket.url);
      socket.current = ws;
      ws.onopen = () =>
        ws.send(
          JSON.stringify({
            type: "hello",
            version: SOCKET_MESSAGES_VERSION,
            token: ticket.token,
            lastSeq: lastSeq.current,
          } satisfies ClientMessage),
        );
      ws.onmessage = (message) => {
        const parsed = parseServerMessage(String(message.data));
        // A server of another version (the page outlived an upgrade) or a broken message: say so rather than fold it.
        if (!parsed.ok) return setNotice(`${parsed.reason} Reload the page.`);
        const m = parsed.message;
        if (m.type === "welcome") {
          retry = 500;
          setConnected(true);
          setNotice(null);
          setViewers(m.viewers);
          setMayRun(m.mayRun);
          receive(m.events);
        } else if (m.type === "access") setMayRun(m.mayRun);
        else if (m.type === "events") receive(m.events);
        else if (m.type === "presence") setViewers(m.viewers);
        else if (m.type === "robot") setRobot({ connected: m.connected, detail: m.detail });
        else if (m.type === "annotation") setAnnotations((a) => [...a, m.annotation]);
        else if (m.type === "codes")
          setCodes((c) => [...c.filter((x) => !m.codes.some((y) => y.id === x.id)), ...m.codes]);
        else if (m.type === "halted") {
          const requestId = m.requestId;
          setTimeout(() => {
            if (pending.current.has(requestId))
              setLogBehind(
                "The robot was stopped, but the stop is not in the log yet: the database is not answering. It is written as soon as the database is back.",
              );
          }, 1000);
        } else if (m.type === "ack" || m.type === "rejected") {
          setLogBehind(null);
          const settle = m.requestId ? pending.current.get(m.requestId) : undefined;
          const command = m.requestId ? (sent.current.get(m.requestId) ?? null) : null;
          if (m.requestId) {
            pending.current.delete(m.requestId);
            sent.current.delete(m.requestId);
          }
          if (m.type === "rejected") setRefusal({ reason: m.reason, command, atSeq: lastSeq.current });
          settle?.(m.type === "ack" ? { ok: true } : { ok: false, reason: m.reason });
        }
      };
      ws.onclose = (event) => {
        setConnected(false);
        for (const settle of pending.current.values())
          settle({ ok: false, reason: "The connection dropped before the server confirmed this." });
        pending.current.clear();
        sent.current.clear();
        if (stopped) return;
        // Shut out (no longer a member, account disabled): say why and stay disconnected.
        if (event.code === 4403) {
          stopped = true;
          setMayRun(false);
          setNotice(event.reason || "You may no longer follow this trial.");
          return;
        }
        setNotice("Connection lost: reconnecting…");
        retry = Math.min(retry * 2, 5000);
        setTimeout(connect, retry);
      };
    };
    void connect();
    return () => {
      stopped = true;
      socket.current?.close();
    };
    // The connection lives as long as the page shows this trial.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [trialId]);

  const request = useCallback((message: (requestId: string) => ClientMessage, command?: Command): Promise<Outcome> => {
    const ws = socket.current;
    if (!ws || ws.readyState !== WebSocket.OPEN)
      return Promise.resolve({ ok: false, reason: "Not connected to the trial yet." });
    const requestId = crypto.randomUUID();
    return new Promise((settle) => {
      pending.current.set(requestId, settle);
      if (command) sent.current.set(requestId, command);
      ws.send(JSON.stringify(message(requestId)));
    });
  }, []);

  // Events only ever arrive appended: each batch is applied to the state so far, never refolded from the start.
  const folded = useRef<{ protocol: TrialProtocol; count: number; state: TrialState } | null>(null);
  const state = useMemo(() => {
    const f = folded.current;
    if (f?.protocol !== protocol || events.length < f.count) {
      folded.current = { protocol, count: events.length, state: fold(protocol, events) };
    } else if (events.length > f.count) {
      folded.current = { protocol, count: events.length, state: applyAll(f.state, events.slice(f.count)) };
    }
    return folded.current!.state;
  }, [protocol, events]);
  return {
    /** What the page must say now: the connection's trouble first, else a refusal that still applies. */
    notice: notice ?? logBehind ?? refusalInForce(refusal, protocol, state)?.reason ?? null,
    state,
    events,
    viewers,
    annotations,
    codes,
    connected,
    robot,
    mayRun,
    command: (command: WizardCommand) =>
      request(
        (requestId) => ({ type: "command", requestId, command }),
        // The engine's form of it: the server gives an unscripted action its id; a sound's end is the action's.
        command.kind === "unscripted"
          ? { ...command, actionId: crypto.randomUUID() }
          : command.kind === "played"
            ? command.failed
              ? { kind: "failed", actionId: command.actionId, reason: command.failed }
              : { kind: "completed", actionId: command.actionId }
            : command,
      ),
    annotate: (label: string, note = "") => request((requestId) => ({ type: "annotate", requestId, label, note })),
    code: (mark: { schemeVersionId: string; setId: string; codeId: string; modifiers?: string[] }) =>
      request((requestId) => ({ type: "code", requestId, modifiers: [], ...mark })),
  };
}
