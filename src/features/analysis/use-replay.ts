"use client";
// The analysis page's replay: a connection to the trial runtime opened on the
// first Replay (not before: most visits replay nothing), which owns the replay
// on the simulated robot. Closing the page closes it, and the replay stops.
import { useMutation } from "@tanstack/react-query";
import { useCallback, useEffect, useRef, useState } from "react";
import {
  parseServerMessage,
  SOCKET_MESSAGES_VERSION,
  type ClientMessage,
  type ServerMessage,
} from "@/core/socket/messages";
import { useTRPC } from "@/lib/trpc";

export type ReplayStatus = Extract<ServerMessage, { type: "replay" }>;

export function useReplay(trialId: string) {
  const trpc = useTRPC();
  const tokenFor = useMutation(trpc.trials.socketToken.mutationOptions());
  const [status, setStatus] = useState<ReplayStatus | null>(null);
  const [problem, setProblem] = useState<string | null>(null);
  // The page's one connection, opened on the first Replay.
  const socket = useRef<Promise<WebSocket> | null>(null);

  useEffect(
    () => () => {
      void socket.current?.then((ws) => ws.close()).catch(() => undefined);
    },
    [],
  );

  const connect = useCallback(async () => {
    const ticket = await tokenFor.mutateAsync({ trialId });
    const ws = new WebSocket(ticket.url);
    return new Promise<WebSocket>((ready, fail) => {
      ws.onopen = () =>
        ws.send(
          JSON.stringify({
            type: "hello",
            version: SOCKET_MESSAGES_VERSION,
            token: ticket.token,
            lastSeq: 0,
          } satisfies ClientMessage),
        );
      ws.onmessage = (message) => {
        const parsed = parseServerMessage(String(message.data));
        if (!parsed.ok) return setProblem(`${parsed.reason} Reload the page.`);
        const m = parsed.message;
        if (m.type === "welcome") ready(ws);
        else if (m.type === "replay") setStatus(m);
        else if (m.type === "rejected") setProblem(m.reason);
        else if (m.type === "ack") setProblem(null);
      };
      ws.onclose = (event) => {
        socket.current = null;
        setStatus((s) => (s?.playing ? { ...s, playing: false, detail: "The connection to the runtime closed." } : s));
        fail(new Error(event.reason || "The trial runtime could not be reached."));
      };
    });
  }, [trialId, tokenFor.mutateAsync]);

  const send = useCallback(
    async (message: ClientMessage) => {
      try {
        socket.current ??= connect();
        (await socket.current).send(JSON.stringify(message));
      } catch (error) {
        socket.current = null;
        setProblem(error instanceof Error ? error.message : String(error));
      }
    },
    [connect],
  );

  return {
    status,
    problem,
    play: (fromMs: number, speed: number) =>
      send({ type: "replay", requestId: crypto.randomUUID(), fromMs: Math.max(0, Math.round(fromMs)), speed }),
    stop: () => (socket.current ? send({ type: "replay_stop", requestId: crypto.randomUUID() }) : Promise.resolve()),
  };
}
