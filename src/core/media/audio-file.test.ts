import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { silentWav as wav } from "../../../tests/support/audio";
import { audioFacts } from "./audio-file";

const bytes = (...parts: Array<string | number[] | Uint8Array>) =>
  new Uint8Array(parts.flatMap((p) => (typeof p === "string" ? [...p].map((c) => c.charCodeAt(0)) : [...p])));
const le32 = (n: number) => [n & 255, (n >> 8) & 255, (n >> 16) & 255, (n >>> 24) & 255];
const le16 = (n: number) => [n & 255, (n >> 8) & 255];

/** An Ogg page with this granule position and payload (no checksum: the reader does not check it). */
const page = (granule: number, payload: number[]) =>
  bytes("OggS", [0, 0], le32(granule), le32(0), le32(1), le32(0), le32(0), [1, payload.length], payload);
const vorbisHead = bytes("\u0001vorbis", le32(0), [1], le32(44100), new Array(13).fill(0));
const opusHead = bytes("OpusHead", [1, 1], le16(312), le32(48000), [0, 0, 0]);

describe("audioFacts", () => {
  it.each<[string, Uint8Array, { kind: string; mimeType: string; durationMs: number | null }]>([
    ["a PCM WAV", wav(250), { kind: "wav", mimeType: "audio/wav", durationMs: 250 }],
    [
      "a WAV whose recorder never filled in the data size",
      wav(100, 0xffffffff),
      { kind: "wav", mimeType: "audio/wav", durationMs: 100 },
    ],
    [
      "an MP3 with an ID3 tag (45 frames of 576 samples at 22.05 kHz)",
      new Uint8Array(readFileSync("tests/fixtures/audio/gsutil-test.mp3")),
      { kind: "mp3", mimeType: "audio/mpeg", durationMs: 1176 },
    ],
    [
      "an Ogg Vorbis file: the last page's granule at the header's rate",
      bytes(page(0, [...vorbisHead]), page(88200, [0])),
      { kind: "ogg", mimeType: "audio/ogg", durationMs: 2000 },
    ],
    [
      "an Ogg Opus file: 48 kHz less the pre-skip",
      bytes(page(0, [...opusHead]), page(48312, [0])),
      { kind: "ogg", mimeType: "audio/ogg", durationMs: 1000 },
    ],
  ])("%s", (_, file, facts) => {
    expect(audioFacts(file)).toEqual(facts);
  });

  it.each<[string, Uint8Array]>([
    ["a PNG image", bytes([0x89], "PNG\r\n", [0x1a, 10], new Array(20).fill(0))],
    ["a text file named .mp3", bytes("not a sound at all")],
    ["a WebM recording", bytes([0x1a, 0x45, 0xdf, 0xa3], new Array(20).fill(0))],
    ["an Ogg video (Theora)", bytes(page(0, [...bytes("\u0080theora", new Array(20).fill(0))]))],
    ["an empty file", new Uint8Array(0)],
  ])("refuses %s", (_, file) => {
    expect(audioFacts(file)).toBeNull();
  });
});
