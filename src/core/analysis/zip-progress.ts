// How far a zip streamed as it is made has come: the names of the files
// that have begun to arrive, read from their local headers as the bytes
// come in. The study's zip says how many trials it holds, but not its
// length (unknown until its end), so the researcher's progress counts the
// trials' records that have arrived. Sizes in these headers are left out
// (written after each file), so the scan looks at every byte; a name is
// taken only when its header is whole, and a chunk may end mid-header.

const SIGNATURE = [0x50, 0x4b, 0x03, 0x04];
const HEADER = 30;
/** Longer names are not ours: a look-alike inside compressed data is skipped, not waited for. */
const MAX_NAME = 512;

/** A counter fed the zip's chunks in order; it returns how many files whose name matches have begun so far. */
export function zipEntryCounter(matches: (name: string) => boolean) {
  let carry = new Uint8Array(0);
  let count = 0;
  const decoder = new TextDecoder();
  return (chunk: Uint8Array): number => {
    const bytes = new Uint8Array(carry.length + chunk.length);
    bytes.set(carry);
    bytes.set(chunk, carry.length);
    let i = 0;
    for (; i + HEADER <= bytes.length; i++) {
      if (!SIGNATURE.every((b, k) => bytes[i + k] === b)) continue;
      const nameLength = bytes[i + 26]! | (bytes[i + 27]! << 8);
      if (nameLength > MAX_NAME) continue;
      if (i + HEADER + nameLength > bytes.length) break;
      if (matches(decoder.decode(bytes.subarray(i + HEADER, i + HEADER + nameLength)))) count++;
      i += HEADER + nameLength - 1;
    }
    // What may still begin a header: from an incomplete one, or the last bytes too short to hold one.
    carry = bytes.slice(Math.min(i, Math.max(0, bytes.length - HEADER + 1)));
    return count;
  };
}

/** A trial's record in the study's zip: one per trial, so counting them counts the trials done. */
export const isTrialRecord = (name: string) => /^trials\/[^/]+\.json$/.test(name);
