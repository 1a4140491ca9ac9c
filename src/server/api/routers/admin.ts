import { TRPCError } from "@trpc/server";
import { asc, desc, eq, like, sql } from "drizzle-orm";
import { alias } from "drizzle-orm/pg-core";
import { z } from "zod";
import { AUDIT_AREA_VALUES } from "@/core/access/audit";
import { SYSTEM_ROLES } from "@/core/access/policy";
import { audit } from "../../audit";
import { createAccount } from "../../auth/accounts";
import { auditLog, participants, login, pluginRepositories, studies, user } from "@/store/schema";
import { guarded, router } from "../trpc";
import { id, text } from "../validation";

const role = z.enum(SYSTEM_ROLES, { error: `must be one of ${SYSTEM_ROLES.join(", ")}` });

function notSelf(actorId: string, userId: string, what: string) {
  if (actorId === userId)
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: `You cannot ${what} your own account; ask another administrator.`,
    });
}

// The account an entry is about, beside the account that acted.
const targetUser = alias(user, "target_user");

export const adminRouter = router({
  users: router({
    list: guarded("admin.users").query(({ ctx }) =>
      ctx.db
        .select({
          id: user.id,
          name: user.name,
          email: user.email,
          role: user.role,
          disabled: user.disabled,
          createdAt: user.createdAt,
        })
        .from(user)
        .orderBy(asc(user.name)),
    ),

    create: guarded("admin.users")
      .input(
        z.object({
          name: text("Name", 200),
          email: z.email("must be an email address"),
          password: z.string().min(8, "must be at least 8 characters").max(200, "must be at most 200 characters"),
          role,
        }),
      )
      .mutation(async ({ ctx, input }) => {
        const [taken] = await ctx.db
          .select({ id: user.id })
          .from(user)
          .where(eq(user.email, input.email.toLowerCase()));
        if (taken) throw new TRPCError({ code: "CONFLICT", message: `An account already uses ${input.email}.` });
        const created = await createAccount(ctx.db, input);
        await audit(ctx.db, {
          actorId: ctx.user.id,
          action: "user.create",
          target: created.id,
          details: { email: created.email, role: input.role },
        });
        return { id: created.id, name: created.name, email: created.email, role: input.role };
      }),

    setRole: guarded("admin.users")
      .input(z.object({ userId: id, role }))
      .mutation(async ({ ctx, input }) => {
        notSelf(ctx.user.id, input.userId, "change the role of");
        return ctx.db.transaction(async (tx) => {
          const [row] = await tx
            .update(user)
            .set({ role: input.role, updatedAt: new Date() })
            .where(eq(user.id, input.userId))
            .returning();
          if (!row) throw new TRPCError({ code: "NOT_FOUND", message: "No such account." });
          await audit(tx, {
            actorId: ctx.user.id,
            action: "user.role",
            target: input.userId,
            details: { role: input.role },
          });
          return { id: row.id, role: row.role };
        });
      }),

    setDisabled: guarded("admin.users")
      .input(z.object({ userId: id, disabled: z.boolean() }))
      .mutation(async ({ ctx, input }) => {
        notSelf(ctx.user.id, input.userId, "disable");
        return ctx.db.transaction(async (tx) => {
          const [row] = await tx
            .update(user)
            .set({ disabled: input.disabled, updatedAt: new Date() })
            .where(eq(user.id, input.userId))
            .returning();
          if (!row) throw new TRPCError({ code: "NOT_FOUND", message: "No such account." });
          // A disabled account is signed out everywhere at once.
          if (input.disabled) await tx.delete(login).where(eq(login.userId, input.userId));
          await audit(tx, {
            actorId: ctx.user.id,
            action: input.disabled ? "user.disable" : "user.enable",
            target: input.userId,
          });
          return { id: row.id, disabled: row.disabled };
        });
      }),
  }),

  auditLog: guarded("admin.users")
    .input(
      z.object({ limit: z.number().int().min(1).max(500).default(100), area: z.enum(AUDIT_AREA_VALUES).optional() }),
    )
    .query(({ ctx, input }) =>
      ctx.db
        .select({
          id: auditLog.id,
          at: auditLog.at,
          action: auditLog.action,
          target: auditLog.target,
          // The target is an id; the account's name, the participant's code or the repository's name says what it was.
          targetName: sql<
            string | null
          >`coalesce(${targetUser.name}, ${participants.code}, ${pluginRepositories.name})`,
          details: auditLog.details,
          actor: user.name,
          studyId: auditLog.studyId,
          studyTitle: studies.title,
        })
        .from(auditLog)
        .leftJoin(user, eq(user.id, auditLog.actorId))
        .leftJoin(studies, eq(studies.id, auditLog.studyId))
        .leftJoin(targetUser, eq(targetUser.id, auditLog.target))
        .leftJoin(participants, eq(participants.id, auditLog.target))
        .leftJoin(pluginRepositories, eq(pluginRepositories.id, auditLog.target))
        // Actions are "area.verb[.detail]", so an area is a prefix up to its dot.
        .where(input.area ? like(auditLog.action, `${input.area}.%`) : undefined)
        .orderBy(desc(auditLog.at))
        .limit(input.limit),
    ),
});
