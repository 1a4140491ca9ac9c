"use client";
// The browser's side of the trial socket: connects with a fresh token (each
// works once, so every reconnection asks for a new one), resumes from the last
// event it saw after any drop, and applies the events to the trial's state
// with the same engine the server uses. While connected it keeps a heartbeat
// (heartbeat.ts), so that a runtime that stops answering is shown at once.
import { useMutation } from "@tanstack/react-query";
import { useCallback, useEffect, useMemo, useRef, useState } from "react";
import { applyAll, type Command, fold, type TrialProtocol, type TrialState } from "@/core/trial";
import { type Refusal, refusalInForce } from "@/core/trial/refusals";
import {
  parseServerMessage,
  SOCKET_MESSAGES_VERSION,
  type ClientMessage,
  type ServerMessage,
  type Signal,
  type Viewer,
  type WireEvent,
  type WizardCommand,
} from "@/core/socket/messages";
import { welcomeJoiner } from "@/core/socket/welcome";
import { useTRPC } from "@/lib/trpc";
import type { LiveRobotState } from "@/core/robots/live-state";
import type { RuntimeState } from "@/core/trial/connections";
import { type Heartbeat, startHeartbeat } from "./heartbeat";

export type Annotation = Extract<ServerMessage, { type: "annotation" }>["annotation"];
/** One of my code events as the runtime confirmed it. */
export type LiveCode = Extract<ServerMessage, { type: "codes" }>["codes"][number];
type Outcome = { ok: true } | { ok: false; reason: string };
export type IceServers = Extract<ServerMessage, { type: "welcome" }>["iceServers"];
export type SignalListener = (from: string, signal: Signal) => void;
export type CameraFrame = Omit<Extract<ServerMessage, { type: "camera" }>, "type">;

export function useTrialSocket(trialId: string, protocol: TrialProtocol) {
  const trpc = useTRPC();
  const tokenFor = useMutation(trpc.trials.socketToken.mutationOptions());
  const [events, setEvents] = useState<WireEvent[]>([]);
  const [viewers, setViewers] = useState<Viewer[]>([]);
  const [annotations, setAnnotations] = useState<Annotation[]>([]);
  // My own codes as the runtime wrote them this visit (the page merges them with those loaded before).
  const [codes, setCodes] = useState<LiveCode[]>([]);
  const [runtime, setRuntime] = useState<RuntimeState>("reconnecting");
  const [robot, setRobot] = useState<{ connected: boolean; detail?: string; name?: string } | null>(null);
  const [robotState, setRobotState] = useState<LiveRobotState | null>(null);
  // About the connection (lost, shut out, another version): stays until the connection changes.
  const [notice, setNotice] = useState<string | null>(null);
  // About the trial (a command refused): stays only while the trial is as it was when refused.
  const [refusal, setRefusal] = useState<Refusal | null>(null);
  // A stop that reached the robot but is not logged yet, a second after: the page says the log is behind.
  const [logBehind, setLogBehind] = useState<string | null>(null);
  // Whether the server lets me command this trial (role, assigned wizard), as it last said.
  const [mayRun, setMayRun] = useState<boolean | null>(null);
  // Live video: this connection's name among the trial's, and the STUN/TURN servers to use.
  const [peer, setPeer] = useState<{ peerId: string; iceServers: IceServers } | null>(null);
  const signalListeners = useRef(new Set<SignalListener>());
  // Signals that came before the video listened (an offer can beat the watcher's first render): kept, in order,
  // for the first listener, or the wizard's one offer to this page would be lost and the picture never come.
  const unheardSignals = useRef<Array<Parameters<SignalListener>>>([]);
  // The robot's camera goes straight to the picture that shows it: a frame re-renders nothing else.
  const cameraListeners = useRef(new Set<(frame: CameraFrame) => void>());
  // Whether this connection gets the robot's camera now, as last said (null until welcomed): the runtime sends
  // frames until told otherwise, and a page hidden or without the picture says so, so that none are sent for nothing.
  const cameraSaid = useRef<boolean | null>(null);
  // Signals' and the camera's outcomes are theirs: a refused one never becomes the page's notice.
  const quietRequests = useRef(new Set<string>());
  const socket = useRef<WebSocket | null>(null);
  const lastSeq = useRef(0);
  // Each request awaiting its answer: what was sent (sent again, as a retry, after a reconnect) and, for a
  // command, its engine form, so that a refusal can be checked against the trial as it moves on.
  const pending = useRef(
    new Map<string, { settle: (o: Outcome) => void; message: ClientMessage; command: Command | null }>(),
  );

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
    let heartbeat: Heartbeat | null = null;
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
      const join = welcomeJoiner();
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
        heartbeat?.heard(parsed.message);
        // A long log comes in parts ahead of the welcome: held until it, then the welcome carries it all.
        const joined = join(parsed.message);
        if (!joined.ok) return setNotice(`${joined.reason} Reload the page.`);
        const m = joined.message;
        if (!m) return;
        if (m.type === "welcome") {
          retry = 500;
          setRuntime("live");
          heartbeat?.stop();
          heartbeat = startHeartbeat((ping) => ws.send(JSON.stringify(ping)), setRuntime);
          setNotice(null);
          setViewers(m.viewers);
          setMayRun(m.mayRun);
          setPeer({ peerId: m.peerId, iceServers: m.iceServers });
          cameraSaid.current = true;
          sayCamera();
          receive(m.events);
          // Commands sent before the connection dropped: asked again by their id, answered with what became
          // of them, never carried out twice nor late.
          for (const { message } of pending.current.values())
            if (message.type === "command")
              ws.send(JSON.stringify({ ...message, retry: true } satisfies ClientMessage));
        } else if (m.type === "access") setMayRun(m.mayRun);
        else if (m.type === "events") receive(m.events);
        else if (m.type === "presence") setViewers(m.viewers);
        // The robot's name comes with the welcome; a later change of connection keeps it.
        else if (m.type === "robot")
          setRobot((r) => ({ connected: m.connected, detail: m.detail, name: m.name ?? r?.name }));
        else if (m.type === "robotState") {
          const { type: _, ...state } = m;
          setRobotState(state);
        } else if (m.type === "annotation") setAnnotations((a) => [...a, m.annotation]);
        else if (m.type === "camera") for (const show of cameraListeners.current) show(m);
        else if (m.type === "signal") {
          if (signalListeners.current.size === 0) unheardSignals.current.push([m.peerId, m.signal]);
          for (const listen of signalListeners.current) listen(m.peerId, m.signal);
        } else if ((m.type === "ack" || m.type === "rejected") && m.requestId && quietRequests.current.has(m.requestId))
          quietRequests.current.delete(m.requestId);
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
          const request = m.requestId ? pending.current.get(m.requestId) : undefined;
          if (m.requestId) pending.current.delete(m.requestId);
          if (m.type === "rejected")
            setRefusal({ reason: m.reason, command: request?.command ?? null, atSeq: lastSeq.current });
          request?.settle(m.type === "ack" ? { ok: true } : { ok: false, reason: m.reason });
        }
      };
      ws.onclose = (event) => {
        heartbeat?.stop();
        heartbeat = null;
        setRuntime("reconnecting");
        setPeer(null);
        cameraSaid.current = null;
        quietRequests.current.clear();
        unheardSignals.current = [];
        // An annotation or a signal is not asked again (no idempotency key); a command is, once reconnected.
        const dropped = (all: boolean) => {
          for (const [id, { settle, message }] of pending.current)
            if (all || message.type !== "command") {
              pending.current.delete(id);
              settle({ ok: false, reason: "The connection dropped before the server confirmed this." });
            }
        };
        dropped(stopped);
        if (stopped) return;
        // Shut out (no longer a member, account disabled): say why and stay disconnected.
        if (event.code === 4403) {
          dropped(true);
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
      heartbeat?.stop();
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
      const sent = message(requestId);
      pending.current.set(requestId, { settle, message: sent, command: command ?? null });
      ws.send(JSON.stringify(sent));
    });
  }, []);

  /** Sends a request whose answer is nobody's notice, fire and forget; false when not connected. */
  const sendQuietly = useCallback((message: (requestId: string) => ClientMessage) => {
    const ws = socket.current;
    if (!ws || ws.readyState !== WebSocket.OPEN) return false;
    const requestId = crypto.randomUUID();
    quietRequests.current.add(requestId);
    ws.send(JSON.stringify(message(requestId)));
    return true;
  }, []);

  /** Sends a live video signal, fire and forget: the video copes with a lost one, the trial never waits on it. */
  const signal = useCallback(
    (peerId: string, signal: Signal) =>
      void sendQuietly((requestId) => ({ type: "signal", requestId, peerId, signal })),
    [sendQuietly],
  );
  const onSignal = useCallback((listen: SignalListener) => {
    signalListeners.current.add(listen);
    for (const [peerId, signal] of unheardSignals.current.splice(0)) listen(peerId, signal);
    return () => void signalListeners.current.delete(listen);
  }, []);

  /** Tells the runtime when the page starts or stops showing the robot's camera (a picture shown, the tab visible). */
  const sayCamera = useCallback(() => {
    const watch = cameraListeners.current.size > 0 && document.visibilityState !== "hidden";
    if (cameraSaid.current === null || watch === cameraSaid.current) return;
    if (sendQuietly((requestId) => ({ type: "camera", requestId, watch }))) cameraSaid.current = watch;
  }, [sendQuietly]);
  useEffect(() => {
    document.addEventListener("visibilitychange", sayCamera);
    return () => document.removeEventListener("visibilitychange", sayCamera);
  }, [sayCamera]);
  const onCamera = useCallback(
    (show: (frame: CameraFrame) => void) => {
      cameraListeners.current.add(show);
      sayCamera();
      return () => {
        cameraListeners.current.delete(show);
        sayCamera();
      };
    },
    [sayCamera],
  );
  const video = useMemo(() => (peer ? { ...peer, signal, onSignal } : null), [peer, signal, onSignal]);

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
    /** The trial runtime: live, connected but not answering (frozen), or reconnecting. */
    runtime,
    /** Whether anything can reach the trial now: the runtime is connected and answering. */
    connected: runtime === "live",
    robot,
    /** What the robot is doing now (null until the runtime says). */
    robotState,
    mayRun,
    /** Live video's side of the socket: null until welcomed (and while reconnecting). */
    video,
    /** The robot's camera frames, as they arrive. */
    onCamera,
    command: (command: WizardCommand) =>
      request(
        // The moment the wizard asked, on the page's clock: every hop drops the command once it is too old.
        (requestId) => ({ type: "command", requestId, command, at: Date.now() }),
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
