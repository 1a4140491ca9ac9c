// What an uploaded sound is, read from its bytes, never from its name or the
// type the browser claims: WAV, MP3 or Ogg (Vorbis or Opus), which every
// browser and the robots' players can play. Its length comes from the file's
// own headers where they say (WAV's byte rate, Ogg's last granule, MP3's
// frames); null when they do not, and the sound still plays.

export type AudioKind = "wav" | "mp3" | "ogg";

export interface AudioFacts {
  kind: AudioKind;
  mimeType: string;
  durationMs: number | null;
}

const MIME: Record<AudioKind, string> = { wav: "audio/wav", mp3: "audio/mpeg", ogg: "audio/ogg" };

const ascii = (b: Uint8Array, at: number, text: string) =>
  at + text.length <= b.length && [...text].every((c, i) => b[at + i] === c.charCodeAt(0));
const u16 = (b: Uint8Array, at: number) => b[at]! | (b[at + 1]! << 8);
const u32 = (b: Uint8Array, at: number) => (u16(b, at) | (u16(b, at + 2) << 16)) >>> 0;

/** The sound's kind and length, or null for anything that is not WAV, MP3 or Ogg audio. */
export function audioFacts(bytes: Uint8Array): AudioFacts | null {
  const kind = kindOf(bytes);
  if (!kind) return null;
  const duration = kind === "wav" ? wavMs(bytes) : kind === "ogg" ? oggMs(bytes) : mp3Ms(bytes);
  return { kind, mimeType: MIME[kind], durationMs: duration === null ? null : Math.round(duration) };
}

function kindOf(b: Uint8Array): AudioKind | null {
  if (ascii(b, 0, "RIFF") && ascii(b, 8, "WAVE")) return "wav";
  if (ascii(b, 0, "OggS") && (ascii(b, 28, "\u0001vorbis") || ascii(b, 28, "OpusHead"))) return "ogg";
  if (ascii(b, 0, "ID3") || mp3Frame(b, 0)) return "mp3";
  return null;
}

function wavMs(b: Uint8Array): number | null {
  let byteRate = 0;
  for (let at = 12; at + 8 <= b.length; ) {
    const size = u32(b, at + 4);
    if (ascii(b, at, "fmt ")) byteRate = u32(b, at + 16);
    // A recorder that never went back to fill the size writes 0 or 0xFFFFFFFF: the rest of the file is the data.
    if (ascii(b, at, "data") && byteRate > 0) return (Math.min(size, b.length - at - 8) / byteRate) * 1000;
    at += 8 + size + (size % 2);
  }
  return null;
}

function oggMs(b: Uint8Array): number | null {
  // Opus always counts 48 kHz samples, less the encoder's pre-skip; Vorbis says its rate.
  const opus = ascii(b, 28, "OpusHead");
  const rate = opus ? 48000 : u32(b, 28 + 12);
  const skip = opus ? u16(b, 28 + 10) : 0;
  for (let at = b.length - 27; at >= 0; at--) {
    if (!ascii(b, at, "OggS")) continue;
    const granule = u32(b, at + 6) + u32(b, at + 10) * 2 ** 32;
    return rate > 0 ? (Math.max(0, granule - skip) / rate) * 1000 : null;
  }
  return null;
}

const BITRATES = {
  1: [0, 32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320],
  2: [0, 8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160],
};
const RATES = { 1: [44100, 48000, 32000], 2: [22050, 24000, 16000], 2.5: [11025, 12000, 8000] };

/** An MPEG audio layer III frame header at `at`: its length in bytes and in seconds. */
function mp3Frame(b: Uint8Array, at: number): { bytes: number; seconds: number } | null {
  if (at + 4 > b.length || b[at] !== 0xff || (b[at + 1]! & 0xe0) !== 0xe0) return null;
  const version = ({ 0: 2.5, 2: 2, 3: 1 } as const)[((b[at + 1]! >> 3) & 3) as 0 | 2 | 3];
  const layer = (b[at + 1]! >> 1) & 3;
  if (!version || layer !== 1) return null;
  const kbps = BITRATES[version === 1 ? 1 : 2][b[at + 2]! >> 4];
  const rate = RATES[version][(b[at + 2]! >> 2) & 3];
  if (!kbps || !rate) return null;
  const samples = version === 1 ? 1152 : 576;
  const padding = (b[at + 2]! >> 1) & 1;
  return { bytes: Math.floor(((samples / 8) * kbps * 1000) / rate) + padding, seconds: samples / rate };
}

function mp3Ms(b: Uint8Array): number | null {
  // An ID3v2 tag first: its size is written in 7-bit bytes.
  let at = ascii(b, 0, "ID3") ? 10 + ((b[6]! << 21) | (b[7]! << 14) | (b[8]! << 7) | b[9]!) : 0;
  let seconds = 0;
  let frames = 0;
  for (let frame = mp3Frame(b, at); frame; frame = mp3Frame(b, at)) {
    seconds += frame.seconds;
    frames++;
    at += frame.bytes;
  }
  return frames > 0 ? seconds * 1000 : null;
}
