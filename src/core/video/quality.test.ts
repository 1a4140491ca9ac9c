import { describe, expect, it } from "vitest";
import { type VideoReading, videoQuality } from "./quality";

const at = (atMs: number, over: Partial<VideoReading> = {}): VideoReading => ({
  atMs,
  bytesReceived: 0,
  packetsReceived: 0,
  packetsLost: 0,
  roundTripSeconds: 0.012,
  ...over,
});

describe("a live video's quality, in words", () => {
  it.each<[string, VideoReading, VideoReading, Partial<ReturnType<typeof videoQuality>>]>([
    [
      "a local network: 1.2 Mbit/s, nothing lost, 12 ms",
      at(0),
      at(2000, { bytesReceived: 300_000, packetsReceived: 300 }),
      {
        kbps: 1200,
        lossPercent: 0,
        roundTripMs: 12,
        level: "good",
        words: "Good picture (1.2 Mbit/s, 0% of packets lost, 12 ms there and back).",
      },
    ],
    [
      "5% of packets lost",
      at(0),
      at(1000, { bytesReceived: 100_000, packetsReceived: 95, packetsLost: 5 }),
      {
        lossPercent: 5,
        level: "fair",
        words: "Fair picture: it may stutter (800 kbit/s, 5% of packets lost, 12 ms there and back).",
      },
    ],
    [
      "a long round trip",
      at(0),
      at(1000, { bytesReceived: 100_000, packetsReceived: 100, roundTripSeconds: 0.5 }),
      { roundTripMs: 500, level: "poor" },
    ],
    [
      "nothing arriving",
      at(0, { bytesReceived: 5000 }),
      at(1000, { bytesReceived: 5000, roundTripSeconds: null }),
      {
        kbps: 0,
        level: "poor",
        words: "Poor picture: expect freezes (no video arriving, 0% of packets lost, delay not measured yet).",
      },
    ],
    [
      "counters only count up: a restart is not a negative rate",
      at(0, { bytesReceived: 9000, packetsReceived: 90 }),
      at(1000, { bytesReceived: 100, packetsReceived: 1 }),
      { kbps: 0, lossPercent: 0 },
    ],
  ])("%s", (_name, before, now, expected) => {
    expect(videoQuality(before, now)).toMatchObject(expected);
  });
});
