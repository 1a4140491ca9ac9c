// Sounds for the tests, made in code: a PCM WAV of silence (8 kHz, 16-bit
// mono, 16000 bytes a second) that every browser plays.
const ascii = (text: string) => [...text].map((c) => c.charCodeAt(0));
const le32 = (n: number) => [n & 255, (n >> 8) & 255, (n >> 16) & 255, (n >>> 24) & 255];
const le16 = (n: number) => [n & 255, (n >> 8) & 255];

/** `ms` of silence; `dataSize` as the header states it (a recorder that never filled it in writes 0xFFFFFFFF). */
export function silentWav(ms: number, dataSize = ms * 16): Uint8Array<ArrayBuffer> {
  const fmt = [...le16(1), ...le16(1), ...le32(8000), ...le32(16000), ...le16(2), ...le16(16)];
  return new Uint8Array([
    ...ascii("RIFF"),
    ...le32(36 + ms * 16),
    ...ascii("WAVE"),
    ...ascii("fmt "),
    ...le32(16),
    ...fmt,
    ...ascii("data"),
    ...le32(dataSize),
    ...new Array<number>(ms * 16).fill(0),
  ]);
}
