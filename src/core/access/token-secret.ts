// How a personal access token's secret is made, and the hash the server keeps instead of it.
import { createHash, randomBytes } from "node:crypto";
import { TOKEN_PREFIX } from "./access-token";

/** 256 random bits: guessing one, or reversing its SHA-256, is out of reach; no slow hash is needed. */
export const newTokenSecret = (bytes: Uint8Array = randomBytes(32)) =>
  `${TOKEN_PREFIX}${Buffer.from(bytes).toString("base64url")}`;

export const hashTokenSecret = (secret: string) => createHash("sha256").update(secret).digest("hex");
