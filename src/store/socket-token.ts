// Short-lived, single-use passes the app signs for the trial runtime's socket.
// A token proves only who and which trial: the runtime looks up the caller's
// role itself (and keeps it fresh), so nothing here can go stale or be raised.
// Signed with a key of its own, derived from the server secret, so a token can
// never stand in for anything the auth secret signs, nor the other way round.
import { createHmac, randomBytes, timingSafeEqual } from "node:crypto";

export interface SocketClaims {
  /** Random; the runtime records it at hello, so each token works once. */
  tokenId: string;
  userId: string;
  trialId: string;
  /** Expiry, milliseconds since the epoch. */
  exp: number;
}

export const TOKEN_LIFETIME_MS = 60_000;

const keyOf = (secret: string) => createHmac("sha256", secret).update("hristudio socket tokens v1").digest();
const sign = (body: string, secret: string) => createHmac("sha256", keyOf(secret)).update(body).digest("base64url");

export function signSocketToken(who: { userId: string; trialId: string }, secret: string, now = Date.now()): string {
  const claims: SocketClaims = {
    tokenId: randomBytes(18).toString("base64url"),
    userId: who.userId,
    trialId: who.trialId,
    exp: now + TOKEN_LIFETIME_MS,
  };
  const body = Buffer.from(JSON.stringify(claims)).toString("base64url");
  return `${body}.${sign(body, secret)}`;
}

export function verifySocketToken(token: string, secret: string, now = Date.now()): SocketClaims | null {
  const [body, mac, extra] = token.split(".");
  if (!body || !mac || extra !== undefined) return null;
  const expected = Buffer.from(sign(body, secret));
  const given = Buffer.from(mac);
  if (expected.length !== given.length || !timingSafeEqual(expected, given)) return null;
  try {
    const c = JSON.parse(Buffer.from(body, "base64url").toString("utf8")) as Partial<SocketClaims>;
    const complete =
      typeof c.tokenId === "string" &&
      typeof c.userId === "string" &&
      typeof c.trialId === "string" &&
      typeof c.exp === "number";
    return complete && c.exp! > now ? (c as SocketClaims) : null;
  } catch {
    return null;
  }
}
