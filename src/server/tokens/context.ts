// A request to the analysis API, seen through its personal access token: the
// caller is the token's owner as the account is now (a disabled account, a
// lost membership or a lowered role take effect at once), limited to the
// token's studies and to reading. No sign-in cookie is ever looked at here.
import { and, eq, isNull, ne, or } from "drizzle-orm";
import { bearerSecret, type TOKEN_REFUSALS, tokenState } from "@/core/access/access-token";
import { hashTokenSecret } from "@/core/access/token-secret";
import { answered, type Database } from "@/store/client";
import { accessTokenStudies, accessTokens, user } from "@/store/schema";
import type { Context } from "../api/trpc";
import { audit } from "../audit";
import { server, toSignedInUser } from "../context";

export type TokenRefusal = keyof typeof TOKEN_REFUSALS;

export async function contextFromToken(
  headers: Headers,
  request: string,
): Promise<{ context: Context } | { refused: TokenRefusal }> {
  const secret = bearerSecret(headers.get("authorization"));
  if (!secret) return { refused: "missing" };
  const { db, auth: _, ...parts } = server();
  // The request's first question to the database: one that does not answer fails it here (see signedInUser).
  const [found] = await answered(
    db
      .select({ token: accessTokens, owner: user })
      .from(accessTokens)
      .innerJoin(user, eq(user.id, accessTokens.userId))
      .where(eq(accessTokens.secretHash, hashTokenSecret(secret))),
    "The database did not answer the access token lookup.",
  );
  if (!found) return { refused: "unknown" };
  const state = tokenState(found.token, new Date());
  if (state !== "active") return { refused: state };
  const owner = toSignedInUser(found.owner);
  if (!owner) return { refused: "disabled" };
  const scope = await db
    .select({ studyId: accessTokenStudies.studyId })
    .from(accessTokenStudies)
    .where(eq(accessTokenStudies.tokenId, found.token.id));
  await recordUse(db, found.token, request);
  return {
    context: { db, ...parts, user: owner, token: { id: found.token.id, studyIds: scope.map((s) => s.studyId) } },
  };
}

/**
 * Every use is remembered as the token's last use; the audit log gets the
 * first use of each day (UTC), with that request. A nightly script reading a
 * table per trial would otherwise write hundreds of entries a night and bury
 * the changes the log is there to show; who held which token, for which
 * studies, is already in its token.create entry.
 */
async function recordUse(db: Database, token: typeof accessTokens.$inferSelect, request: string) {
  const now = new Date();
  const today = now.toISOString().slice(0, 10);
  await db.transaction(async (tx) => {
    const [first] = await tx
      .update(accessTokens)
      .set({ lastUsedAt: now, auditedOn: today })
      .where(and(eq(accessTokens.id, token.id), or(isNull(accessTokens.auditedOn), ne(accessTokens.auditedOn, today))))
      .returning({ id: accessTokens.id });
    if (first)
      await audit(tx, {
        actorId: token.userId,
        action: "token.use",
        target: token.id,
        details: { name: token.name, request },
      });
    else await tx.update(accessTokens).set({ lastUsedAt: now }).where(eq(accessTokens.id, token.id));
  });
}
