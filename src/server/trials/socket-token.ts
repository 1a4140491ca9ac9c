// Short-lived tokens the app signs for the trial runtime's socket: who, which
// trial, in what role. HMAC-SHA256 with the server's auth secret.
import { createHmac, timingSafeEqual } from "node:crypto";
import type { StudyRole } from "@/core/access/policy";

export interface SocketClaims {
  userId: string;
  name: string;
  trialId: string;
  studyRole: StudyRole;
  /** Expiry, milliseconds since the epoch. */
  exp: number;
}

export const TOKEN_LIFETIME_MS = 60_000;

const sign = (body: string, secret: string) => createHmac("sha256", secret).update(body).digest("base64url");

export function signSocketToken(claims: Omit<SocketClaims, "exp">, secret: string, now = Date.now()): string {
  const body = Buffer.from(JSON.stringify({ ...claims, exp: now + TOKEN_LIFETIME_MS })).toString("base64url");
  return `${body}.${sign(body, secret)}`;
}

export function verifySocketToken(token: string, secret: string, now = Date.now()): SocketClaims | null {
  const [body, mac] = token.split(".");
  if (!body || !mac) return null;
  const expected = Buffer.from(sign(body, secret));
  const given = Buffer.from(mac);
  if (expected.length !== given.length || !timingSafeEqual(expected, given)) return null;
  try {
    const claims = JSON.parse(Buffer.from(body, "base64url").toString("utf8")) as SocketClaims;
    return claims.exp > now ? claims : null;
  } catch {
    return null;
  }
}
