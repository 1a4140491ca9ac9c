// Personal access tokens: how a secret is read from a request, and whether
// it still works (how one is made and stored: token-secret.ts). No node:
// imports, so the Access tokens page can share the limits.

/** Marks a string as ours, so a leaked one is recognisable (and secret scanners can match it). */
export const TOKEN_PREFIX = "hri_";
export const EXPIRY_DAYS = { min: 1, max: 365 } as const;

/** The secret of `Authorization: Bearer <secret>`, or null when there is none of ours. */
export function bearerSecret(authorization: string | null): string | null {
  const match = /^Bearer\s+(\S+)\s*$/i.exec(authorization ?? "");
  const secret = match?.[1];
  return secret?.startsWith(TOKEN_PREFIX) ? secret : null;
}

export type TokenState = "active" | "expired" | "revoked";

export function tokenState(token: { expiresAt: Date; revokedAt: Date | null }, now: Date): TokenState {
  if (token.revokedAt) return "revoked";
  return token.expiresAt.getTime() <= now.getTime() ? "expired" : "active";
}

/** Why a request's token was refused, in words its holder can act on. */
export const TOKEN_REFUSALS = {
  missing:
    "This API needs a personal access token: send the header Authorization: Bearer <token> (Account → Access tokens).",
  unknown: "This access token is not known: check it was copied whole, or create a new one (Account → Access tokens).",
  expired: "This access token has expired: create a new one (Account → Access tokens).",
  revoked: "This access token was revoked: create a new one (Account → Access tokens).",
  disabled: "The account this access token belongs to is disabled.",
} as const;
