// A study's coding schemes (built and versioned like questionnaires) and the
// codes observers mark in its trials: live over the trial socket, or added and
// corrected afterwards here, each observer only ever changing their own tier.
import { TRPCError } from "@trpc/server";
import { asc, eq, sql } from "drizzle-orm";
import { z } from "zod";

import { countedSchema } from "@/core/coding/counted";
import { SCHEME_TEMPLATES, blankScheme, schemeTemplate } from "@/core/coding/templates";
import { codeOfTrial, codeView, trialCodes } from "@/store/code-events";
import { qualified } from "@/store/qualified";
import { codeEvents, codingSchemeVersions, codingSchemes, user } from "@/store/schema";
import { studyAgreement } from "../../coding/agreement";
import { checkedScheme, insertScheme, keptCounted, publishScheme, publishedSchemes } from "../../coding/schemes";
import { router, studyProcedure } from "../trpc";
import { id, text } from "../validation";

const ms = z.number().finite().min(0).max(86_400_000);
const modifiers = z.array(z.string().min(1).max(100)).max(20).default([]);

/** A code event's times, checked for its kind: a point has no end, a state ends after it starts. */
function timesFor(kind: "point" | "state", startMs: number, endMs: number | null) {
  if (kind === "point") return { startMs, endMs: null };
  if (endMs === null || endMs < startMs)
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: "Please correct: endMs: a state must end at or after its start",
    });
  return { startMs, endMs };
}

export const codingRouter = router({
  schemes: studyProcedure("trial.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: codingSchemes.id,
        name: codingSchemes.name,
        latestVersion: sql<
          number | null
        >`(select max(${codingSchemeVersions.version}) from ${codingSchemeVersions} where ${codingSchemeVersions.schemeId} = ${qualified(codingSchemes.id)})`,
        latestVersionId: sql<
          string | null
        >`(select ${codingSchemeVersions.id} from ${codingSchemeVersions} where ${codingSchemeVersions.schemeId} = ${qualified(codingSchemes.id)} order by ${codingSchemeVersions.version} desc limit 1)`,
      })
      .from(codingSchemes)
      .where(eq(codingSchemes.studyId, ctx.studyId))
      .orderBy(asc(codingSchemes.name)),
  ),

  scheme: studyProcedure("trial.read", "codingScheme", z.object({ codingSchemeId: id })).query(({ ctx }) => ({
    ...ctx.row,
    draft: checkedScheme(ctx.row.draft),
  })),

  createScheme: studyProcedure(
    "experiment.edit",
    "study",
    z.object({
      studyId: id,
      name: text("Name", 200).optional(),
      template: z.enum(SCHEME_TEMPLATES).nullable().default(null),
    }),
  ).mutation(({ ctx, input }) => {
    const draft = input.template ? schemeTemplate(input.template) : blankScheme(input.name ?? "New coding scheme");
    return insertScheme(ctx.db, ctx.studyId, input.name ? { ...draft, name: input.name } : draft);
  }),

  saveScheme: studyProcedure(
    "experiment.edit",
    "codingScheme",
    z.object({ codingSchemeId: id, definition: z.unknown() }),
  ).mutation(async ({ ctx, input }) => {
    const draft = checkedScheme(input.definition);
    await ctx.db
      .update(codingSchemes)
      .set({ name: draft.name, draft, updatedAt: new Date() })
      .where(eq(codingSchemes.id, ctx.row.id));
    return { saved: ctx.row.id };
  }),

  /** Freezes the draft as a numbered version: every code event points at the exact version used. */
  publishScheme: studyProcedure("version.publish", "codingScheme", z.object({ codingSchemeId: id })).mutation(
    ({ ctx }) => publishScheme(ctx.db, ctx.row.id, ctx.user.id),
  ),

  /** What an observer of this trial codes with, and the codes they marked in it so far (their own tier). */
  forTrial: studyProcedure("trial.read", "trial", z.object({ trialId: id })).query(async ({ ctx }) => ({
    schemes: await publishedSchemes(ctx.db, ctx.studyId),
    mine: (await trialCodes(ctx.db, ctx.row.id)).filter((c) => c.observerId === ctx.user.id).map(codeView),
  })),

  /** Every observer's codes of a trial, each with their name: the tiers of the analysis page. */
  codes: studyProcedure("data.read", "trial", z.object({ trialId: id })).query(async ({ ctx }) => {
    const rows = await ctx.db
      .select({ code: codeEvents, observerName: user.name })
      .from(codeEvents)
      .leftJoin(user, eq(user.id, codeEvents.observerId))
      .where(eq(codeEvents.trialId, ctx.row.id))
      .orderBy(asc(codeEvents.startMs), asc(codeEvents.id));
    return rows.map((r) => ({ ...codeView(r.code), observerName: r.observerName ?? "(former member)" }));
  }),

  /**
   * Cohen's kappa per set between every two observers who coded with this
   * version: per trial both coded, and pooled over them (the study's figure).
   * Counted as the scheme keeps it (`keepCounted`), unless the request chooses otherwise.
   */
  agreement: studyProcedure(
    "data.read",
    "schemeVersion",
    z.object({
      schemeVersionId: id,
      sliceMs: countedSchema.shape.sliceMs.unwrap().optional(),
      window: countedSchema.shape.window.unwrap().optional(),
      stepIds: countedSchema.shape.stepIds.unwrap().optional(),
    }),
  ).query(async ({ ctx, input }) => {
    const kept = await keptCounted(ctx.db, ctx.row.schemeId);
    const counted = {
      sliceMs: input.sliceMs ?? kept.sliceMs,
      window: input.window ?? kept.window,
      stepIds: input.stepIds ?? kept.stepIds,
    };
    const found = await studyAgreement(ctx.db, ctx.studyId, ctx.row.id, checkedScheme(ctx.row.definition), counted);
    return { ...found, counted, kept };
  }),

  /** How the scheme's agreement is counted, for the Results tab and the methods text alike. */
  keepCounted: studyProcedure(
    "experiment.edit",
    "codingScheme",
    z.object({ codingSchemeId: id, counted: countedSchema }),
  ).mutation(async ({ ctx, input }) => {
    const draft = { ...checkedScheme(ctx.row.draft), counted: input.counted };
    await ctx.db.update(codingSchemes).set({ draft, updatedAt: new Date() }).where(eq(codingSchemes.id, ctx.row.id));
    return input.counted;
  }),

  /** A code marked afterwards, against the recording, in the caller's own tier. */
  addCode: studyProcedure(
    "annotation.create",
    "trial",
    z.object({
      trialId: id,
      schemeVersionId: id,
      setId: z.string().min(1).max(100),
      codeId: z.string().min(1).max(100),
      startMs: ms,
      endMs: ms.nullable().default(null),
      modifiers,
    }),
  ).mutation(async ({ ctx, input }) => {
    const found = await codeOfTrial(ctx.db, ctx.row.id, { ...input, versionId: input.schemeVersionId });
    if (!found.ok) throw new TRPCError({ code: "BAD_REQUEST", message: found.reason });
    const [row] = await ctx.db
      .insert(codeEvents)
      .values({
        trialId: ctx.row.id,
        observerId: ctx.user.id,
        versionId: input.schemeVersionId,
        setId: found.set.id,
        codeId: found.code.id,
        kind: found.code.kind,
        ...timesFor(found.code.kind, input.startMs, input.endMs),
        modifiers: input.modifiers,
      })
      .returning();
    return codeView(row!);
  }),

  /** Moves one of the caller's own codes (a state's end too). */
  moveCode: studyProcedure(
    "annotation.create",
    "codeEvent",
    z.object({ codeEventId: id, startMs: ms, endMs: ms.nullable().default(null) }),
  ).mutation(async ({ ctx, input }) => {
    assertOwn(ctx.row.observerId, ctx.user.id);
    const [row] = await ctx.db
      .update(codeEvents)
      .set({ ...timesFor(ctx.row.kind, input.startMs, input.endMs), updatedAt: new Date() })
      .where(eq(codeEvents.id, ctx.row.id))
      .returning();
    return codeView(row!);
  }),

  deleteCode: studyProcedure("annotation.create", "codeEvent", z.object({ codeEventId: id })).mutation(
    async ({ ctx }) => {
      assertOwn(ctx.row.observerId, ctx.user.id);
      await ctx.db.delete(codeEvents).where(eq(codeEvents.id, ctx.row.id));
      return { deleted: ctx.row.id };
    },
  ),
});

/** Each observer's tier is theirs alone: agreement means nothing if one could edit another's codes. */
function assertOwn(observerId: string | null, userId: string) {
  if (observerId !== userId)
    throw new TRPCError({ code: "FORBIDDEN", message: "This code is another observer's: only they may change it." });
}
