// Personal access tokens for the analysis API: made, listed and revoked by
// their owner alone. A token reaches only studies whose data its owner may
// read when it is made, and, each time it is used, still may (src/server/tokens).
import { TRPCError } from "@trpc/server";
import { and, asc, desc, eq, inArray, isNull } from "drizzle-orm";
import { z } from "zod";
import { EXPIRY_DAYS, tokenState } from "@/core/access/access-token";
import { hashTokenSecret, newTokenSecret } from "@/core/access/token-secret";
import { studyRoleMay } from "@/core/access/policy";
import type { Database } from "@/store/client";
import { accessTokenStudies, accessTokens, studies, studyMembers } from "@/store/schema";
import { audit } from "../../audit";
import { guarded, router } from "../trpc";
import { id, text } from "../validation";

const DAY_MS = 86_400_000;

/** The studies whose analysis data this person may read: those a token may be made for. */
async function readableStudies(db: Database, userId: string) {
  const rows = await db
    .select({ id: studies.id, title: studies.title, role: studyMembers.role })
    .from(studies)
    .innerJoin(studyMembers, and(eq(studyMembers.studyId, studies.id), eq(studyMembers.userId, userId)))
    .orderBy(asc(studies.title));
  return rows.filter((s) => studyRoleMay(s.role, "data.read"));
}

export const tokensRouter = router({
  /** What the New token form offers. */
  studies: guarded("token.manage").query(({ ctx }) => readableStudies(ctx.db, ctx.user.id)),

  /** The secret is in this answer only: the server keeps its hash. */
  create: guarded("token.manage")
    .input(
      z.object({
        name: text("Name", 100),
        studyIds: z.array(id).min(1, "choose at least one study").max(200, "may list at most 200 studies"),
        expiresInDays: z
          .number({ error: "must be a number of days" })
          .int("must be a whole number of days")
          .min(EXPIRY_DAYS.min, `must be at least ${EXPIRY_DAYS.min} day`)
          .max(EXPIRY_DAYS.max, `must be at most ${EXPIRY_DAYS.max} days`),
      }),
    )
    .mutation(async ({ ctx, input }) => {
      const readable = new Map((await readableStudies(ctx.db, ctx.user.id)).map((s) => [s.id, s]));
      const studyIds = [...new Set(input.studyIds)];
      studyIds.forEach((studyId, i) => {
        // Another study, one I only run trials in, or no study at all: all read the same.
        if (!readable.has(studyId))
          throw new TRPCError({
            code: "BAD_REQUEST",
            message: `Please correct: studyIds.${i}: not a study whose data you may read`,
          });
      });
      const secret = newTokenSecret();
      const expiresAt = new Date(Date.now() + input.expiresInDays * DAY_MS);
      return ctx.db.transaction(async (tx) => {
        const [token] = await tx
          .insert(accessTokens)
          .values({ userId: ctx.user.id, name: input.name, secretHash: hashTokenSecret(secret), expiresAt })
          .returning({ id: accessTokens.id });
        await tx.insert(accessTokenStudies).values(studyIds.map((studyId) => ({ tokenId: token!.id, studyId })));
        await audit(tx, {
          actorId: ctx.user.id,
          action: "token.create",
          target: token!.id,
          details: { name: input.name, studies: studyIds.map((s) => readable.get(s)!.title), expiresAt },
        });
        return { id: token!.id, name: input.name, secret, expiresAt };
      });
    }),

  /** My tokens, newest first, with the studies each reaches and whether it still works. */
  list: guarded("token.manage").query(async ({ ctx }) => {
    const tokens = await ctx.db
      .select({
        id: accessTokens.id,
        name: accessTokens.name,
        createdAt: accessTokens.createdAt,
        expiresAt: accessTokens.expiresAt,
        lastUsedAt: accessTokens.lastUsedAt,
        revokedAt: accessTokens.revokedAt,
      })
      .from(accessTokens)
      .where(eq(accessTokens.userId, ctx.user.id))
      .orderBy(desc(accessTokens.createdAt));
    const scope = tokens.length
      ? await ctx.db
          .select({ tokenId: accessTokenStudies.tokenId, id: studies.id, title: studies.title })
          .from(accessTokenStudies)
          .innerJoin(studies, eq(studies.id, accessTokenStudies.studyId))
          .where(
            inArray(
              accessTokenStudies.tokenId,
              tokens.map((t) => t.id),
            ),
          )
          .orderBy(asc(studies.title))
      : [];
    const now = new Date();
    return tokens.map((t) => ({
      ...t,
      state: tokenState(t, now),
      studies: scope.filter((s) => s.tokenId === t.id).map(({ id, title }) => ({ id, title })),
    }));
  }),

  revoke: guarded("token.manage")
    .input(z.object({ tokenId: id }))
    .mutation(async ({ ctx, input }) => {
      const [token] = await ctx.db
        .select()
        .from(accessTokens)
        .where(and(eq(accessTokens.id, input.tokenId), eq(accessTokens.userId, ctx.user.id)));
      // Someone else's token reads like no token at all.
      if (!token) throw new TRPCError({ code: "NOT_FOUND", message: "No such access token of yours." });
      return ctx.db.transaction(async (tx) => {
        const [revoked] = await tx
          .update(accessTokens)
          .set({ revokedAt: new Date() })
          .where(and(eq(accessTokens.id, token.id), isNull(accessTokens.revokedAt)))
          .returning({ revokedAt: accessTokens.revokedAt });
        // Revoking twice changes nothing and writes nothing.
        if (revoked)
          await audit(tx, {
            actorId: ctx.user.id,
            action: "token.revoke",
            target: token.id,
            details: { name: token.name },
          });
        return { revoked: token.id, revokedAt: revoked?.revokedAt ?? token.revokedAt };
      });
    }),
});
