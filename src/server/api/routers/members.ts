import { TRPCError } from "@trpc/server";
import { and, asc, eq } from "drizzle-orm";
import { z } from "zod";
import { STUDY_ROLES } from "@/core/access/policy";
import { audit } from "../../audit";
import type { Database } from "@/store/client";
import { studies, studyMembers, user } from "@/store/schema";
import { router, studyProcedure } from "../trpc";
import { id } from "../validation";

const role = z.enum(STUDY_ROLES, { error: `must be one of ${STUDY_ROLES.join(", ")}` });

async function ownerCount(db: Pick<Database, "select">, studyId: string) {
  const owners = await db
    .select({ userId: studyMembers.userId })
    .from(studyMembers)
    .where(and(eq(studyMembers.studyId, studyId), eq(studyMembers.role, "owner")));
  return owners.length;
}

/** Serialises membership changes of one study, so two can never remove the last owners at once. */
async function lockStudy(tx: Pick<Database, "select">, studyId: string) {
  await tx.select({ id: studies.id }).from(studies).where(eq(studies.id, studyId)).for("update");
}

async function memberRole(db: Pick<Database, "select">, studyId: string, userId: string) {
  const [row] = await db
    .select({ role: studyMembers.role })
    .from(studyMembers)
    .where(and(eq(studyMembers.studyId, studyId), eq(studyMembers.userId, userId)));
  if (!row) throw new TRPCError({ code: "NOT_FOUND", message: "That person is not a member of this study." });
  return row.role;
}

const LAST_OWNER = "A study needs at least one owner: make someone else owner first.";

export const membersRouter = router({
  list: studyProcedure("member.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        userId: user.id,
        name: user.name,
        email: user.email,
        role: studyMembers.role,
        addedAt: studyMembers.addedAt,
      })
      .from(studyMembers)
      .innerJoin(user, eq(user.id, studyMembers.userId))
      .where(eq(studyMembers.studyId, ctx.studyId))
      .orderBy(asc(user.name)),
  ),

  add: studyProcedure(
    "member.manage",
    "study",
    z.object({ studyId: id, email: z.email("must be an email address"), role }),
  ).mutation(async ({ ctx, input }) => {
    const [person] = await ctx.db.select().from(user).where(eq(user.email, input.email.toLowerCase()));
    if (!person) {
      throw new TRPCError({
        code: "NOT_FOUND",
        message: `No account uses ${input.email}. Ask an administrator to create it first.`,
      });
    }
    return ctx.db.transaction(async (tx) => {
      const added = await tx
        .insert(studyMembers)
        .values({ studyId: ctx.studyId, userId: person.id, role: input.role })
        .onConflictDoNothing()
        .returning();
      if (added.length === 0)
        throw new TRPCError({ code: "CONFLICT", message: `${person.name} is already a member of this study.` });
      await audit(tx, {
        actorId: ctx.user.id,
        studyId: ctx.studyId,
        action: "member.add",
        target: person.id,
        details: { role: input.role },
      });
      return { userId: person.id, name: person.name, email: person.email, role: input.role };
    });
  }),

  changeRole: studyProcedure("member.manage", "study", z.object({ studyId: id, userId: id, role })).mutation(
    ({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        await lockStudy(tx, ctx.studyId);
        const before = await memberRole(tx, ctx.studyId, input.userId);
        if (before === "owner" && input.role !== "owner" && (await ownerCount(tx, ctx.studyId)) === 1) {
          throw new TRPCError({ code: "BAD_REQUEST", message: LAST_OWNER });
        }
        await tx
          .update(studyMembers)
          .set({ role: input.role })
          .where(and(eq(studyMembers.studyId, ctx.studyId), eq(studyMembers.userId, input.userId)));
        await audit(tx, {
          actorId: ctx.user.id,
          studyId: ctx.studyId,
          action: "member.role",
          target: input.userId,
          details: { from: before, to: input.role },
        });
        return { userId: input.userId, role: input.role };
      }),
  ),

  remove: studyProcedure("member.manage", "study", z.object({ studyId: id, userId: id })).mutation(({ ctx, input }) =>
    ctx.db.transaction(async (tx) => {
      await lockStudy(tx, ctx.studyId);
      const before = await memberRole(tx, ctx.studyId, input.userId);
      if (before === "owner" && (await ownerCount(tx, ctx.studyId)) === 1) {
        throw new TRPCError({ code: "BAD_REQUEST", message: LAST_OWNER });
      }
      await tx
        .delete(studyMembers)
        .where(and(eq(studyMembers.studyId, ctx.studyId), eq(studyMembers.userId, input.userId)));
      await audit(tx, {
        actorId: ctx.user.id,
        studyId: ctx.studyId,
        action: "member.remove",
        target: input.userId,
        details: { role: before },
      });
      return { removed: input.userId };
    }),
  ),
});
