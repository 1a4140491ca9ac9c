// Chrome's MediaRecorder writes WebM files with no duration (it cannot know
// it while recording), so players cannot seek them. When a recording is
// finished we know its length: this writes the Duration element into the
// Segment's Info, in place when there is one, else inserted. The file's head
// up to the end of its Info is enough: the rest follows unchanged, so a long
// recording is patched in its first part and streamed.
// WebM is EBML: elements of (ID, size, data), IDs and sizes as variable-length integers.

const EBML = 0x1a45dfa3;
const SEGMENT = 0x18538067;
const INFO = 0x1549a966;
const TIMECODE_SCALE = 0x2ad7b1;
const DURATION = 0x4489;
const CLUSTER = 0x1f43b675;
const CLUSTER_TIMECODE = 0xe7;
const BLOCK_GROUP = 0xa0;
const BLOCK = 0xa1;
const SIMPLE_BLOCK = 0xa3;

interface Element {
  id: number;
  /** Where the element starts (its ID). */
  start: number;
  /** Where its data starts. */
  dataStart: number;
  /** Data size; null when "unknown" (a live recording's Segment). */
  size: number | null;
  sizeLength: number;
}

function vintLength(first: number): number {
  for (let length = 1; length <= 8; length++) if (first & (0x80 >> (length - 1))) return length;
  throw new Error("not a WebM file: bad variable-length integer");
}

function readElement(bytes: Uint8Array, at: number): Element {
  const idLength = vintLength(bytes[at]!);
  let id = 0;
  for (let i = 0; i < idLength; i++) id = id * 256 + bytes[at + i]!;
  const sizeAt = at + idLength;
  const sizeLength = vintLength(bytes[sizeAt]!);
  let size = bytes[sizeAt]! & (0xff >> sizeLength);
  let allOnes = size === 0xff >> sizeLength;
  for (let i = 1; i < sizeLength; i++) {
    size = size * 256 + bytes[sizeAt + i]!;
    allOnes &&= bytes[sizeAt + i] === 0xff;
  }
  return { id, start: at, dataStart: sizeAt + sizeLength, size: allOnes ? null : size, sizeLength };
}

/** A size as an 8-byte variable-length integer: room for anything, and a fixed width. */
function size8(value: number): Uint8Array {
  const out = new Uint8Array(8);
  out[0] = 0x01;
  let rest = value;
  for (let i = 7; i >= 1; i--) {
    out[i] = rest % 256;
    rest = Math.floor(rest / 256);
  }
  return out;
}

function float64(value: number): Uint8Array {
  const out = new Uint8Array(8);
  new DataView(out.buffer).setFloat64(0, value);
  return out;
}

function readUint(bytes: Uint8Array, element: Element): number {
  let value = 0;
  for (let i = 0; i < element.size!; i++) value = value * 256 + bytes[element.dataStart + i]!;
  return value;
}

function children(bytes: Uint8Array, parent: Element, end: number): Element[] {
  const found: Element[] = [];
  for (let at = parent.dataStart; at < Math.min(end, bytes.length); ) {
    // A head of the file may end inside the next element's ID or size: what came before is all there is.
    const child = wholeHeader(bytes, at);
    if (!child) break;
    found.push(child);
    if (child.size === null) break;
    at = child.dataStart + child.size;
  }
  return found;
}

function locateInfo(bytes: Uint8Array) {
  const header = readElement(bytes, 0);
  if (header.id !== EBML || header.size === null) throw new Error("not a WebM file: no EBML header");
  const segment = readElement(bytes, header.dataStart + header.size);
  if (segment.id !== SEGMENT) throw new Error("not a WebM file: no Segment after the header");
  const segmentEnd = segment.size === null ? bytes.length : segment.dataStart + segment.size;
  const info = children(bytes, segment, segmentEnd).find((e) => e.id === INFO);
  if (!info || info.size === null) throw new Error("not a WebM file: its Segment has no Info");
  // Written as a negation so that a size read past the bytes' end (NaN) is refused too.
  if (!(info.dataStart + info.size <= bytes.length)) throw new Error("the WebM file's head is cut off inside its Info");
  const fields = children(bytes, info, info.dataStart + info.size);
  const scale = fields.find((e) => e.id === TIMECODE_SCALE);
  return { segment, info, fields, nsPerTick: scale ? readUint(bytes, scale) : 1_000_000 };
}

/** The duration the file declares, in ms, or null when it declares none. */
export function webmDuration(bytes: Uint8Array): number | null {
  const { fields, nsPerTick } = locateInfo(bytes);
  const duration = fields.find((e) => e.id === DURATION);
  if (!duration) return null;
  const view = new DataView(bytes.buffer, bytes.byteOffset + duration.dataStart, duration.size!);
  const ticks = duration.size === 4 ? view.getFloat32(0) : view.getFloat64(0);
  return (ticks * nsPerTick) / 1e6;
}

/** The element at `at`, or null when the bytes end (or turn to garbage) inside its ID or size. */
function wholeHeader(bytes: Uint8Array, at: number): Element | null {
  try {
    const element = readElement(bytes, at);
    return element.dataStart <= bytes.length ? element : null;
  } catch {
    return null;
  }
}

/**
 * When the file's last frame starts, in ms: the length of a recording whose
 * recorder went away before it could say. Its last part may end anywhere, so
 * the walk stops at the first element the bytes do not hold whole. Null when
 * no frame is found.
 */
export function webmLastFrameMs(bytes: Uint8Array): number | null {
  const { segment, nsPerTick } = locateInfo(bytes);
  let clusterTicks = 0;
  let last: number | null = null;
  for (let at = segment.dataStart; at < bytes.length; ) {
    const element = wholeHeader(bytes, at);
    if (!element) break;
    // A cluster (often of unknown size while live) and a block group hold what is read next: step into them.
    if (element.id === CLUSTER || element.id === BLOCK_GROUP) {
      at = element.dataStart;
      continue;
    }
    if (element.size === null || element.dataStart + element.size > bytes.length) break;
    if (element.id === CLUSTER_TIMECODE) clusterTicks = readUint(bytes, element);
    if ((element.id === SIMPLE_BLOCK || element.id === BLOCK) && element.size >= 4) {
      // A block: its track number (a variable-length integer), then its time from the cluster's, a signed 16 bits.
      const timeAt = element.dataStart + vintLength(bytes[element.dataStart]!);
      const ticks = clusterTicks + new DataView(bytes.buffer, bytes.byteOffset + timeAt, 2).getInt16(0);
      last = Math.max(last ?? 0, (ticks * nsPerTick) / 1e6);
    }
    at = element.dataStart + element.size;
  }
  return last;
}

/** The same file, declaring `durationMs`. */
export function withWebmDuration(bytes: Uint8Array, durationMs: number): Uint8Array {
  const { segment, info, fields, nsPerTick } = locateInfo(bytes);
  const ticks = (durationMs * 1e6) / nsPerTick;
  const existing = fields.find((e) => e.id === DURATION);
  if (existing && (existing.size === 8 || existing.size === 4)) {
    const out = bytes.slice();
    const view = new DataView(out.buffer, existing.dataStart, existing.size);
    if (existing.size === 8) view.setFloat64(0, ticks);
    else view.setFloat32(0, ticks);
    return out;
  }
  const durationElement = new Uint8Array([0x44, 0x89, 0x88, ...float64(ticks)]);
  const infoData = bytes.subarray(info.dataStart, info.dataStart + info.size!);
  const newInfo = new Uint8Array([
    0x15,
    0x49,
    0xa9,
    0x66,
    ...size8(infoData.length + durationElement.length),
    ...infoData,
    ...durationElement,
  ]);
  const grown = newInfo.length - (info.dataStart + info.size! - info.start);
  // A Segment of known size grows by what was inserted; a live one's "unknown" stays as written.
  const segmentSize =
    segment.size === null
      ? bytes.subarray(segment.dataStart - segment.sizeLength, segment.dataStart)
      : size8(segment.size + grown);
  return concat([
    bytes.subarray(0, segment.start),
    bytes.subarray(segment.start, segment.dataStart - segment.sizeLength),
    segmentSize,
    bytes.subarray(segment.dataStart, info.start),
    newInfo,
    bytes.subarray(info.dataStart + info.size!),
  ]);
}

function concat(parts: Uint8Array[]): Uint8Array {
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let at = 0;
  for (const part of parts) {
    out.set(part, at);
    at += part.length;
  }
  return out;
}
