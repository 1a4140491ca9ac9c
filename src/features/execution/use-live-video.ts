"use client";
// Live video with WebRTC, browser to browser: the wizard's page offers its
// camera and microphone (the recorder's own stream) to every other connection
// of the trial; a watcher's page answers and shows it. The trial socket only
// carries the signals. Everything here is apart from the wizard's commands
// and the recording: a failure ends this video, never a command.
import { useEffect, useRef, useState } from "react";
import type { Signal, Viewer } from "@/core/socket/messages";
import { type VideoQuality, type VideoReading, videoQuality } from "@/core/video/quality";
import type { IceServers, SignalListener } from "./use-trial-socket";

export interface VideoChannel {
  peerId: string;
  iceServers: IceServers;
  signal: (peerId: string, signal: Signal) => void;
  onSignal: (listen: SignalListener) => () => void;
}

const STATS_EVERY_MS = 2000;

/** One peer connection, whose ICE candidates wait for the remote description they belong to. */
function connect(video: VideoChannel, peerId: string) {
  const pc = new RTCPeerConnection({ iceServers: video.iceServers });
  const waiting: RTCIceCandidateInit[] = [];
  pc.onicecandidate = (e) => {
    if (e.candidate)
      video.signal(peerId, {
        kind: "candidate",
        candidate: {
          candidate: e.candidate.candidate,
          sdpMid: e.candidate.sdpMid,
          sdpMLineIndex: e.candidate.sdpMLineIndex,
        },
      });
  };
  const receive = async (signal: Signal) => {
    if (signal.kind === "candidate") {
      if (pc.remoteDescription) await pc.addIceCandidate(signal.candidate);
      else waiting.push(signal.candidate);
      return;
    }
    await pc.setRemoteDescription(signal.description);
    for (const candidate of waiting.splice(0)) await pc.addIceCandidate(candidate);
    if (signal.description.type === "offer") {
      await pc.setLocalDescription(await pc.createAnswer());
      video.signal(peerId, { kind: "description", description: { type: "answer", sdp: pc.localDescription!.sdp } });
    }
  };
  return { pc, receive };
}

/** The wizard's side: offers `stream` to every other connection of the trial while there is one. */
export function useVideoSource(video: VideoChannel | null, viewers: Viewer[], stream: MediaStream | null) {
  const peers = useRef(new Map<string, ReturnType<typeof connect>>());
  const [sending, setSending] = useState(0);
  // A new stream or a new socket connection starts every peer afresh.
  useEffect(() => {
    const current = peers.current;
    if (!video || !stream) return;
    const off = video.onSignal((from, signal) => {
      void current
        .get(from)
        ?.receive(signal)
        .catch(() => {});
    });
    return () => {
      off();
      for (const { pc } of current.values()) pc.close();
      current.clear();
      setSending(0);
    };
  }, [video, stream]);
  useEffect(() => {
    const current = peers.current;
    if (!video || !stream) return;
    const here = new Set(viewers.map((v) => v.peerId).filter((p) => p !== video.peerId));
    for (const [peerId, { pc }] of current)
      if (!here.has(peerId)) {
        pc.close();
        current.delete(peerId);
      }
    for (const peerId of here) {
      if (current.has(peerId)) continue;
      const peer = connect(video, peerId);
      current.set(peerId, peer);
      for (const track of stream.getTracks()) peer.pc.addTrack(track, stream);
      void (async () => {
        await peer.pc.setLocalDescription(await peer.pc.createOffer());
        video.signal(peerId, {
          kind: "description",
          description: { type: "offer", sdp: peer.pc.localDescription!.sdp },
        });
      })().catch(() => {});
    }
    setSending(current.size);
  }, [video, viewers, stream]);
  return { sending };
}

/**
 * A watcher's side: answers the wizard's offer, and measures how the video
 * arrives. `viewers` are the trial's connections: when the wizard's page
 * leaves them (closed, crashed), its picture goes at once, not once the
 * connection times out.
 */
export function useVideoWatcher(video: VideoChannel | null, viewers: Viewer[]) {
  const [stream, setStream] = useState<MediaStream | null>(null);
  const [quality, setQuality] = useState<VideoQuality | null>(null);
  const watched = useRef<(ReturnType<typeof connect> & { from: string }) | null>(null);
  useEffect(() => {
    const peer = watched.current;
    if (!peer || viewers.some((v) => v.peerId === peer.from)) return;
    peer.pc.close();
    watched.current = null;
    setStream(null);
  }, [viewers]);
  useEffect(() => {
    if (!video) return;
    let last: VideoReading | null = null;
    const off = video.onSignal((from, signal) => {
      // A new offer (the wizard started again, or another tab) replaces the connection.
      if (signal.kind === "description" && signal.description.type === "offer") {
        watched.current?.pc.close();
        const peer = { ...connect(video, from), from };
        watched.current = peer;
        last = null;
        peer.pc.ontrack = (e) => setStream(e.streams[0] ?? new MediaStream([e.track]));
        peer.pc.onconnectionstatechange = () => {
          if (peer.pc.connectionState === "failed" || peer.pc.connectionState === "closed") setStream(null);
        };
      }
      const peer = watched.current;
      if (peer?.from === from) void peer.receive(signal).catch(() => {});
    });
    const timer = setInterval(() => {
      const pc = watched.current?.pc;
      if (pc?.connectionState !== "connected") return setQuality(null);
      void pc
        .getStats()
        .then((report) => {
          const now = readingOf(report);
          if (last && now) setQuality(videoQuality(last, now));
          last = now;
        })
        .catch(() => {});
    }, STATS_EVERY_MS);
    return () => {
      off();
      clearInterval(timer);
      watched.current?.pc.close();
      watched.current = null;
      setStream(null);
      setQuality(null);
    };
  }, [video]);
  return { stream, quality };
}

function readingOf(report: RTCStatsReport): VideoReading | null {
  let inbound: RTCInboundRtpStreamStats | null = null;
  let roundTripSeconds: number | null = null;
  for (const s of report.values()) {
    if (s.type === "inbound-rtp" && s.kind === "video") inbound = s as RTCInboundRtpStreamStats;
    if (s.type === "candidate-pair" && s.nominated && s.currentRoundTripTime !== undefined)
      roundTripSeconds = s.currentRoundTripTime;
  }
  if (!inbound) return null;
  return {
    atMs: inbound.timestamp,
    bytesReceived: inbound.bytesReceived ?? 0,
    packetsReceived: inbound.packetsReceived ?? 0,
    packetsLost: inbound.packetsLost ?? 0,
    roundTripSeconds,
  };
}
