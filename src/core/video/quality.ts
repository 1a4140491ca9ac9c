// How a watcher's live video is doing, in words, from two readings of
// WebRTC's statistics (RTCPeerConnection.getStats) a few seconds apart.

/** What is read from one getStats report: the incoming video and the connection's round trip. */
export interface VideoReading {
  atMs: number;
  bytesReceived: number;
  packetsReceived: number;
  packetsLost: number;
  /** Seconds, as getStats gives it; null before the first measure. */
  roundTripSeconds: number | null;
}

export interface VideoQuality {
  kbps: number;
  lossPercent: number;
  roundTripMs: number | null;
  level: "good" | "fair" | "poor";
  /** One sentence a watcher understands. */
  words: string;
}

/** Where each measure stops being good, then fair (a video call's usual marks). */
const LOSS = { fair: 2, poor: 8 };
const ROUND_TRIP_MS = { fair: 150, poor: 400 };
const KBPS = { fair: 300, poor: 80 };

export function videoQuality(before: VideoReading, now: VideoReading): VideoQuality {
  const seconds = Math.max((now.atMs - before.atMs) / 1000, 0.001);
  const kbps = Math.max(0, Math.round(((now.bytesReceived - before.bytesReceived) * 8) / 1000 / seconds));
  const received = Math.max(0, now.packetsReceived - before.packetsReceived);
  const lost = Math.max(0, now.packetsLost - before.packetsLost);
  const lossPercent = received + lost ? Math.round((lost / (received + lost)) * 1000) / 10 : 0;
  const roundTripMs = now.roundTripSeconds === null ? null : Math.round(now.roundTripSeconds * 1000);
  const worst = (value: number, marks: { fair: number; poor: number }, higherIsWorse = true) => {
    const past = (mark: number) => (higherIsWorse ? value >= mark : value <= mark);
    return past(marks.poor) ? 2 : past(marks.fair) ? 1 : 0;
  };
  const level = Math.max(
    worst(lossPercent, LOSS),
    roundTripMs === null ? 0 : worst(roundTripMs, ROUND_TRIP_MS),
    worst(kbps, KBPS, false),
  );
  const parts = [
    kbps === 0 ? "no video arriving" : `${kbps >= 1000 ? `${(kbps / 1000).toFixed(1)} Mbit/s` : `${kbps} kbit/s`}`,
    `${lossPercent}% of packets lost`,
    roundTripMs === null ? "delay not measured yet" : `${roundTripMs} ms there and back`,
  ];
  const verdict = ["Good picture", "Fair picture: it may stutter", "Poor picture: expect freezes"][level]!;
  return {
    kbps,
    lossPercent,
    roundTripMs,
    level: (["good", "fair", "poor"] as const)[level]!,
    words: `${verdict} (${parts.join(", ")}).`,
  };
}
