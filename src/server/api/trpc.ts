import { initTRPC, TRPCError } from "@trpc/server";
import { ZodError } from "zod";
import { decide, type Operation, type StudyRole, type SystemRole } from "@/core/access/policy";
import type { Database } from "../db/client";
import { studyAccessOf, studyIdForInput } from "../access/membership";
import type { MediaStorage } from "../media/storage";
import { NOT_BLINDED, type Blinding } from "@/core/studies/blinding";
import { describeIssues, fieldIssues, type FieldIssue } from "./errors";

export interface SessionUser {
  id: string;
  name: string;
  email: string;
  role: SystemRole;
}

export interface Context {
  db: Database;
  user: SessionUser | null;
  /** Signs the trial runtime's socket tokens. */
  secret: string;
  /** Where browsers reach the trial runtime. */
  runtimeUrl: string;
  /** Where recordings are kept, and the largest one accepted. */
  media: { storage: MediaStorage; maxBytes: number };
}

export interface Meta {
  /** Every procedure names the operation it performs; the policy decides. */
  op: Operation | "public";
}

const t = initTRPC
  .context<Context>()
  .meta<Meta>()
  .create({
    errorFormatter({ shape, error }) {
      const issues: FieldIssue[] | null = error.cause instanceof ZodError ? fieldIssues(error.cause) : null;
      return {
        ...shape,
        message: issues ? `Please correct: ${describeIssues(issues)}` : shape.message,
        data: { ...shape.data, issues },
      };
    },
  });

export const router = t.router;
export const createCallerFactory = t.createCallerFactory;

/** Only for procedures that need no account (none hold study data). */
export const publicProcedure = t.procedure.meta({ op: "public" });

export interface AuthorizedContext extends Context {
  user: SessionUser;
  studyId: string | null;
  studyRole: StudyRole | null;
  /** What the study's blinds hide from the caller: procedures strip it from what they return. */
  blinding: Blinding;
}

/**
 * Every non-public procedure passes here: signed in, then the policy, asked
 * with the caller's role in the study the input points at.
 */
export const procedure = t.procedure.use(async ({ ctx, meta, next, getRawInput }) => {
  if (!meta || !meta.op) {
    throw new TRPCError({ code: "INTERNAL_SERVER_ERROR", message: "Procedure declares no operation." });
  }
  if (meta.op === "public") {
    throw new TRPCError({ code: "INTERNAL_SERVER_ERROR", message: "Public procedures use publicProcedure." });
  }
  if (!ctx.user) throw new TRPCError({ code: "UNAUTHORIZED", message: "Please sign in." });
  const studyId = await studyIdForInput(ctx.db, await getRawInput(), meta.op);
  const { role: studyRole, blinding } = studyId ? await studyAccessOf(ctx.db, studyId, ctx.user.id) : { role: null, blinding: NOT_BLINDED };
  const decision = decide({ systemRole: ctx.user.role, studyRole, blinding }, meta.op);
  if (!decision.allow) {
    throw new TRPCError({ code: decision.hidden ? "NOT_FOUND" : "FORBIDDEN", message: decision.reason });
  }
  return next({ ctx: { ...ctx, user: ctx.user, studyId, studyRole, blinding } });
});

/** A procedure guarded by `op`. */
export const guarded = (op: Operation) => procedure.meta({ op });
