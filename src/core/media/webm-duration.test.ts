import { describe, expect, it } from "vitest";
import { webmDuration, webmLastFrameMs, withWebmDuration } from "./webm-duration";

// Minimal WebM files shaped like Chrome's MediaRecorder output: EBML header,
// a Segment (unknown or known size), Info with a TimecodeScale, one Cluster.
const ebmlHeader = [0x1a, 0x45, 0xdf, 0xa3, 0x84, 0x42, 0x82, 0x81, 0x77];
const info = (extra: number[] = []) => {
  const data = [0x2a, 0xd7, 0xb1, 0x83, 0x0f, 0x42, 0x40, 0x4d, 0x80, 0x84, 0x43, 0x68, 0x72, 0x6d, ...extra]; // TimecodeScale 1,000,000; MuxingApp "Chrm"
  return [0x15, 0x49, 0xa9, 0x66, 0x80 | data.length, ...data];
};
const cluster = [0x1f, 0x43, 0xb6, 0x75, 0x83, 0xe7, 0x81, 0x00];
const live = (infoBytes: number[]) =>
  new Uint8Array([
    ...ebmlHeader,
    0x18,
    0x53,
    0x80,
    0x67,
    0x01,
    0xff,
    0xff,
    0xff,
    0xff,
    0xff,
    0xff,
    0xff,
    ...infoBytes,
    ...cluster,
  ]);
const known = (infoBytes: number[]) =>
  new Uint8Array([
    ...ebmlHeader,
    0x18,
    0x53,
    0x80,
    0x67,
    0x80 | (infoBytes.length + cluster.length),
    ...infoBytes,
    ...cluster,
  ]);

describe("WebM duration", () => {
  it.each([
    ["a live recording (Segment of unknown size)", live(info())],
    ["a Segment of known size", known(info())],
  ])("is written into %s that declared none, and everything after it is kept", (_name, file) => {
    expect(webmDuration(file)).toBeNull();
    const fixed = withWebmDuration(file, 12_345.5);
    expect(webmDuration(fixed)).toBeCloseTo(12_345.5, 3);
    expect([...fixed.slice(-cluster.length)]).toEqual(cluster);
    expect(webmDuration(withWebmDuration(fixed, 99_000))).toBeCloseTo(99_000, 3);
  });

  it.each([
    ["a live recording", live(info())],
    ["a Segment of known size", known(info())],
    ["a file with a duration already", live(info([0x44, 0x89, 0x88, 0, 0, 0, 0, 0, 0, 0, 0]))],
  ])("is written the same into any head of %s that holds its Info, the rest following unchanged", (_name, file) => {
    const whole = withWebmDuration(file, 7_000);
    const infoEnd = file.length - cluster.length;
    for (let cut = infoEnd; cut <= file.length; cut++)
      expect([...withWebmDuration(file.subarray(0, cut), 7_000), ...file.subarray(cut)]).toEqual([...whole]);
    for (let cut = 0; cut < infoEnd; cut++) expect(() => withWebmDuration(file.subarray(0, cut), 7_000)).toThrow();
  });

  it("overwrites a duration that is already there, in place", () => {
    const file = live(info([0x44, 0x89, 0x88, 0, 0, 0, 0, 0, 0, 0, 0]));
    const fixed = withWebmDuration(file, 5000);
    expect(fixed.length).toBe(file.length);
    expect(webmDuration(fixed)).toBe(5000);
  });

  it.each([
    ["not WebM at all", new Uint8Array([0x89, 0x50, 0x4e, 0x47]), /no EBML header/],
    ["a header without a Segment", new Uint8Array([...ebmlHeader, ...cluster]), /no Segment/],
  ])("refuses %s with a reason", (_name, file, reason) => {
    expect(() => withWebmDuration(file, 1000)).toThrow(reason);
  });
});

// Clusters as a live recorder writes them: of unknown size (or known), a time, then blocks timed from it.
const UNKNOWN = [0x01, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff];
const block = (ms: number, id = 0xa3) => [id, 0x88, 0x81, (ms >> 8) & 0xff, ms & 0xff, 0x80, 1, 2, 3, 4];
const timedCluster = (ms: number, blocks: number[][], size: "unknown" | "known" = "unknown") => {
  const data = [0xe7, 0x82, (ms >> 8) & 0xff, ms & 0xff, ...blocks.flat()];
  return [0x1f, 0x43, 0xb6, 0x75, ...(size === "unknown" ? UNKNOWN : [0x80 | data.length]), ...data];
};
const recorded = (...clusters: number[][]) =>
  new Uint8Array([...ebmlHeader, 0x18, 0x53, 0x80, 0x67, ...UNKNOWN, ...info(), ...clusters.flat()]);
const inGroup = (ms: number) => [0xa0, 0x8a, ...block(ms, 0xa1)];

describe("WebM's last frame", () => {
  it.each([
    [
      "clusters of unknown size",
      recorded(timedCluster(0, [block(0), block(33)]), timedCluster(1000, [block(500)])),
      1500,
    ],
    [
      "clusters of known size",
      recorded(timedCluster(0, [block(40)], "known"), timedCluster(2000, [block(7)], "known")),
      2007,
    ],
    ["blocks in block groups", recorded(timedCluster(3000, [inGroup(0), inGroup(250)])), 3250],
    [
      "a last part cut in the middle of a block",
      recorded(timedCluster(0, [block(0)]), timedCluster(4000, [block(100), block(200)])).slice(0, -3),
      4100,
    ],
    ["a file cut inside a cluster's header", recorded(timedCluster(0, [block(90)]), [0x1f, 0x43]), 90],
    ["no frame at all", recorded(), null],
  ])("is read from %s", (_name, file, ms) => {
    expect(webmLastFrameMs(file)).toBe(ms);
  });
});
