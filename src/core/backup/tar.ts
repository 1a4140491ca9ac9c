// The backup file is a plain tar archive (POSIX ustar), so `tar -tf` lists it
// and any archiver opens it. These are its 512-byte headers, without I/O.

export const BLOCK = 512;
const OCTAL_SIZE_LIMIT = 8 ** 11; // 8 GiB: beyond it the size is written in base 256, as GNU tar does.

const encoder = new TextEncoder();
const decoder = new TextDecoder();

function writeString(block: Uint8Array, at: number, length: number, text: string) {
  const bytes = encoder.encode(text);
  if (bytes.length > length) throw new Error(`"${text}" is too long for a tar header field of ${length} bytes`);
  block.set(bytes, at);
}

function writeOctal(block: Uint8Array, at: number, length: number, value: number) {
  writeString(block, at, length, value.toString(8).padStart(length - 1, "0"));
}

function writeSize(block: Uint8Array, size: number) {
  if (size < OCTAL_SIZE_LIMIT) return writeOctal(block, 124, 12, size);
  let rest = BigInt(size);
  for (let i = 135; i > 124; i--) {
    block[i] = Number(rest & 0xffn);
    rest >>= 8n;
  }
  block[124] = 0x80;
}

/** Splits a long name into ustar's prefix (up to 155 bytes) and name (up to 100), at a "/". */
export function splitName(path: string): { prefix: string; name: string } {
  if (encoder.encode(path).length <= 100) return { prefix: "", name: path };
  for (let i = path.indexOf("/"); i !== -1; i = path.indexOf("/", i + 1)) {
    const prefix = path.slice(0, i);
    const name = path.slice(i + 1);
    if (encoder.encode(prefix).length <= 155 && encoder.encode(name).length <= 100 && name) return { prefix, name };
  }
  throw new Error(`The name "${path}" is too long to store in the backup file (a tar archive).`);
}

const checksum = (block: Uint8Array) => block.reduce((sum, byte, i) => sum + (i >= 148 && i < 156 ? 32 : byte), 0);

/** The header of a regular file of `size` bytes. */
export function tarHeader(path: string, size: number, modified: Date): Uint8Array {
  if (!Number.isSafeInteger(size) || size < 0) throw new Error(`${size} is not a file size`);
  const block = new Uint8Array(BLOCK);
  const { prefix, name } = splitName(path);
  writeString(block, 0, 100, name);
  writeOctal(block, 100, 8, 0o644);
  writeOctal(block, 108, 8, 0);
  writeOctal(block, 116, 8, 0);
  writeSize(block, size);
  writeOctal(block, 136, 12, Math.floor(modified.getTime() / 1000));
  block[156] = "0".charCodeAt(0);
  writeString(block, 257, 6, "ustar");
  writeString(block, 263, 2, "00");
  writeString(block, 345, 155, prefix);
  writeString(block, 148, 8, `${checksum(block).toString(8).padStart(6, "0")}\0 `);
  return block;
}

function readString(block: Uint8Array, at: number, length: number): string {
  const field = block.subarray(at, at + length);
  const end = field.indexOf(0);
  return decoder.decode(end === -1 ? field : field.subarray(0, end));
}

function readSize(block: Uint8Array): number {
  if (block[124]! & 0x80) {
    let value = 0n;
    for (let i = 125; i < 136; i++) value = (value << 8n) | BigInt(block[i]!);
    return Number(value);
  }
  return Number.parseInt(readString(block, 124, 12).trim() || "0", 8);
}

export type TarEntryHeader = { name: string; size: number; type: string };

/** A header read back; null for the zero block that ends the archive. Refuses a damaged block. */
export function readTarHeader(block: Uint8Array, offset: number): TarEntryHeader | null {
  if (block.length !== BLOCK)
    throw new Error(`The backup file ends in the middle of a header (at byte ${offset}): it is incomplete.`);
  if (block.every((b) => b === 0)) return null;
  const stored = Number.parseInt(readString(block, 148, 8).trim(), 8);
  if (stored !== checksum(block))
    throw new Error(
      `The backup file is damaged at byte ${offset} (a header's checksum does not match), or it is not a backup file.`,
    );
  const prefix = readString(block, 345, 155);
  const name = readString(block, 0, 100);
  return {
    name: prefix ? `${prefix}/${name}` : name,
    size: readSize(block),
    type: String.fromCharCode(block[156] || 48),
  };
}

/** Zero bytes that bring an entry's data up to a whole block. */
export const paddingAfter = (size: number) => (BLOCK - (size % BLOCK)) % BLOCK;
