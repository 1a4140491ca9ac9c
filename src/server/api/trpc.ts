import { initTRPC, TRPCError } from "@trpc/server";
import { ZodError, type z } from "zod";
import { nulPath, nulRefusal } from "@/core/access/input";
import {
  decide,
  isStudyOperation,
  type Operation,
  type StudyOperation,
  type StudyRole,
  type SystemOperation,
  type SystemRole,
} from "@/core/access/policy";
import type { Channels } from "@/core/plugins";
import type { Blinding } from "@/core/studies/blinding";
import { answered, DATABASE_UNAVAILABLE, type Database, databaseUnavailable } from "@/store/client";
import { assertOneStudy } from "../access/membership";
import { studyAccessOf } from "@/store/study-access";
import { keyOf, loadResource, nameOf, type Resource, type ResourceRow } from "../access/resources";
import type { MediaStorage } from "../media/storage";
import { failure } from "@/store/error-reference";
import { describeIssues, fieldIssues, type FieldIssue } from "./errors";

export interface SignedInUser {
  id: string;
  name: string;
  email: string;
  role: SystemRole;
}

export interface Context {
  db: Database;
  /**
   * A trivial question to the database on a connection of its own: a pool busy
   * with slow work is then never taken for a database that does not answer.
   */
  ping: () => Promise<unknown>;
  user: SignedInUser | null;
  /** Signs the trial runtime's socket tokens. */
  secret: string;
  /** Where browsers reach the trial runtime. */
  runtimeUrl: string;
  /** Where recordings are kept, and the largest one accepted. */
  media: { storage: MediaStorage; maxBytes: number };
  /** The ways to the robot this server's settings open: what the designer may call runnable. */
  robotChannels: Channels;
  /** Set for the routes outside tRPC, which answer with their own Response: only they are given a streamed body. */
  streamsFiles?: boolean;
  /**
   * Set when the caller came with a personal access token (the analysis API)
   * rather than a signed-in page: `user` is the token's owner as the account
   * is now, and only the studies listed here can be reached.
   */
  token?: AccessTokenScope;
}

export interface AccessTokenScope {
  id: string;
  studyIds: readonly string[];
}

export interface Meta {
  /** Every procedure names the operation it performs; the policy decides. */
  op: Operation | "public";
  /** A study operation names the kind of row it acts on; the study is that row's. */
  resource?: Resource;
}

const t = initTRPC
  .context<Context>()
  .meta<Meta>()
  .create({
    // Never a stack trace to a client, in any mode.
    isDev: false,
    errorFormatter({ shape, error, path }) {
      const issues: FieldIssue[] | null = error.cause instanceof ZodError ? fieldIssues(error.cause) : null;
      // An unexpected error may carry SQL and its parameters: the client gets a reference instead.
      const message = issues
        ? `Please correct: ${describeIssues(issues)}`
        : error.code === "INTERNAL_SERVER_ERROR"
          ? failure(error.cause ?? error, `procedure ${path ?? "(unknown)"}`).message
          : shape.message;
      return {
        ...shape,
        message,
        data: { code: shape.data.code, httpStatus: shape.data.httpStatus, path: shape.data.path, issues },
      };
    },
  });

export const router = t.router;
export const createCallerFactory = t.createCallerFactory;

/** PostgreSQL cannot store a NUL character: refused here with where it was, before any handler. */
const noNul = t.middleware(async ({ getRawInput, next }) => {
  const at = nulPath(await getRawInput());
  if (at) throw new TRPCError({ code: "BAD_REQUEST", message: nulRefusal(at) });
  return next();
});

/** How long a procedure works before the database is asked whether it still answers, and then how often. */
const WATCH_MS = 3000;
/** A database that answers at all answers `select 1` at once; one that stays silent this long is gone. */
const PROBE_MS = 2000;

const unavailable = (cause: unknown) =>
  new TRPCError({ code: "SERVICE_UNAVAILABLE", message: DATABASE_UNAVAILABLE, cause });

/**
 * Every procedure answers 503 with the plain sentence when the database is
 * away: at once when a query fails because it could not be reached or its
 * connection dropped, and within seconds when the database goes silent
 * partway through (a frozen server keeps its connections open and answers
 * nothing, so the procedure's own query would wait for good). A procedure
 * still working after a few seconds makes the database answer a trivial
 * question; while it does, the procedure is slow but healthy (a large
 * import) and is left to finish. When it does not, the person is answered
 * and the procedure left behind: its writes are in transactions, which
 * commit whole or not at all, and a try again sees whichever it was.
 */
const databaseAnswers = t.middleware(async ({ ctx, next }) => {
  const work = next();
  for (;;) {
    let timer: ReturnType<typeof setTimeout> | undefined;
    const watch = new Promise<"watch">((ok) => {
      timer = setTimeout(() => ok("watch"), WATCH_MS);
    });
    // A procedure that ends while the database is being asked is answered at once, not after the question.
    const done = await Promise.race([work, watch.then(probe)]).finally(() => clearTimeout(timer));
    if (done instanceof TRPCError) throw done;
    if (done !== "answers") {
      if (!done.ok && databaseUnavailable(done.error)) throw unavailable(done.error);
      return done;
    }
  }

  function probe(): Promise<"answers" | TRPCError> {
    return answered(ctx.ping(), "The database did not answer during a request.", PROBE_MS).then(
      () => "answers",
      (error: unknown) => unavailable(error),
    );
  }
});

const watched = t.procedure.use(databaseAnswers);

/** Only for procedures that need no account (none hold study data). */
export const publicProcedure = watched.meta({ op: "public" }).use(noNul);

/** Signed in, and every procedure declares what it does. */
const signedIn = watched.use(noNul).use(async ({ ctx, meta, next }) => {
  if (!meta?.op) throw new TRPCError({ code: "INTERNAL_SERVER_ERROR", message: "Procedure declares no operation." });
  if (meta.op === "public")
    throw new TRPCError({ code: "INTERNAL_SERVER_ERROR", message: "Public procedures use publicProcedure." });
  if (isStudyOperation(meta.op) && !meta.resource)
    throw new TRPCError({
      code: "INTERNAL_SERVER_ERROR",
      message: `Operation ${meta.op} must name the row it acts on.`,
    });
  if (!ctx.user) throw new TRPCError({ code: "UNAUTHORIZED", message: "Please sign in." });
  return next({ ctx: { ...ctx, user: ctx.user } });
});

/** A procedure that touches no study: who may call it depends on the account's system role. */
export const guarded = (op: SystemOperation) =>
  signedIn.meta({ op }).use(({ ctx, next }) => {
    const decision = decide({ systemRole: ctx.user.role, studyRole: null, viaToken: !!ctx.token }, op);
    if (!decision.allow) throw new TRPCError({ code: "FORBIDDEN", message: decision.reason });
    return next();
  });

export interface StudyContext<R extends Resource> {
  studyId: string;
  studyRole: StudyRole;
  /** What the study's blinds hide from the caller: procedures strip it from what they return. */
  blinding: Blinding;
  /** The row the procedure acts on, as stored. */
  row: ResourceRow<R>;
}

/**
 * The caller's access to one row of a study, for `op`: the row is loaded, the
 * study is the row's own, and the policy decides with the caller's role
 * there. An unknown id reads exactly like a row of a study the caller may not
 * see. A procedure that reaches a second study (a copy into another study)
 * asks this again for the row there.
 */
export async function authorize<R extends Resource>(
  db: Database,
  user: SignedInUser,
  op: StudyOperation,
  resource: R,
  id: string,
  /** A personal access token's scope, when the caller came with one. */
  token?: AccessTokenScope | null,
): Promise<StudyContext<R>> {
  const row = await loadResource(db, resource, id);
  // An unknown id reads exactly like a row of a study the caller may not see.
  const notFound = () =>
    new TRPCError({
      code: "NOT_FOUND",
      message: `No such ${nameOf(resource)}, or it belongs to a study you are not a member of.`,
    });
  // A study outside a token's scope reads like one the caller is not a member of.
  if (!row || (token && !token.studyIds.includes(row.studyId))) throw notFound();
  const { role, blinding } = await studyAccessOf(db, row.studyId, user.id);
  const decision = decide({ systemRole: user.role, studyRole: role, blinding, viaToken: !!token }, op);
  if (!decision.allow)
    throw decision.hidden ? notFound() : new TRPCError({ code: "FORBIDDEN", message: decision.reason });
  return { studyId: row.studyId, studyRole: role!, blinding, row };
}

/**
 * A procedure that acts on one row of a study. After its input is validated,
 * the row named by `<resource>Id` is loaded, the study is the row's own, the
 * policy decides with the caller's role there, and any other id in the input
 * (under any key, at any depth) must belong to the same study. The handler
 * receives the loaded row as `ctx.row`: nothing is left for it to forget.
 */
export function studyProcedure<R extends Resource, I extends z.ZodObject>(op: StudyOperation, resource: R, input: I) {
  const key = keyOf(resource);
  return signedIn
    .meta({ op, resource })
    .input(input)
    .use(async ({ ctx, input: parsed, getRawInput, next }) => {
      const id = (parsed as Record<string, unknown>)[key];
      if (typeof id !== "string")
        throw new TRPCError({
          code: "INTERNAL_SERVER_ERROR",
          message: `A procedure on a ${resource} needs ${key} in its input.`,
        });
      const access = await authorize(ctx.db, ctx.user, op, resource, id, ctx.token);
      await assertOneStudy(ctx.db, access.studyId, await getRawInput(), { kind: resource, id });
      return next({ ctx: access });
    });
}
