import { assertWizardOf } from "../../studies/wizard-gate";
import { TRPCError } from "@trpc/server";
import { and, asc, desc, eq, type SQL, sql } from "drizzle-orm";
import { alias, type SelectedFields } from "drizzle-orm/pg-core";
import { z } from "zod";
import { studyRoleMay } from "@/core/access/policy";
import { blindTrial } from "@/core/studies/blinding";
import type { Instrument } from "@/core/questionnaires/definition";
import { publishedScores } from "@/core/questionnaires/published-scores";
import {
  annotations,
  conditions,
  experimentVersions,
  experiments,
  participants,
  trialSamples,
  trials,
  user,
} from "@/store/schema";
import { loadDesign } from "../../experiments/design";
import { snapshotOf } from "@/core/protocol/snapshot";
import { inCondition } from "@/core/protocol/variants";
import { conditionOfTrial } from "@/store/trial-condition";
import { trialLog, trialLogJson } from "@/store/event-store";
import type { Database } from "@/store/client";
import { trialFile } from "../../trials/files";
import { trialPluginNames } from "../../trials/action-names";
import { assertMayTakePart } from "../../studies/consent-gate";
import { assertNotWithdrawn } from "../../trials/withdrawn";
import { assertRunsTrials } from "../../studies/status-gate";
import { signSocketToken } from "@/store/socket-token";
import { qualified } from "@/store/qualified";
import { fileAnswer } from "../file-answer";
import { textStream } from "@/server/trials/text-stream";
import { router, studyProcedure } from "../trpc";
import { liveNow } from "./live-now";
import { id, text } from "../validation";

/** Who created the trial, kept apart from who runs it (its wizard). */
const creator = alias(user, "creator");

const columns = {
  id: trials.id,
  status: trials.status,
  isRehearsal: trials.isRehearsal,
  t0: trials.t0,
  endedAt: trials.endedAt,
  createdAt: trials.createdAt,
  experimentId: trials.experimentId,
  experimentName: experiments.name,
  versionId: trials.versionId,
  version: experimentVersions.version,
  participantId: trials.participantId,
  participantCode: participants.code,
  wizardId: trials.wizardId,
  wizardName: user.name,
  createdBy: trials.createdBy,
  createdByName: creator.name,
  participantWithdrawn: sql<boolean>`coalesce(${participants.consentStatus} = 'withdrawn', false)`,
};

/** Each submitted questionnaire's stored score and instrument, for the study's table of trials. */
const questionnaireScores = sql<Array<{ name: string; instrument: Instrument | null; score: unknown }> | null>`(
  select json_agg(json_build_object('name', q.name, 'instrument', v.definition->>'instrument', 'score', r.score) order by q.name)
  from questionnaire_responses r
  join questionnaire_links l on l.id = r.link_id
  join questionnaire_versions v on v.id = l.version_id
  join questionnaires q on q.id = v.questionnaire_id
  where l.trial_id = ${qualified(trials.id)} and r.status = 'submitted' and r.score is not null)`;

/**
 * A study's trials as its table and a trial's page show them: each with its experiment, version, participant,
 * wizard and creator by name, and what else the caller selects over the same joins (a trial's protocol).
 */
function trialRows<More extends SelectedFields>(db: Database, where: SQL, more: More = {} as More) {
  return db
    .select({ ...columns, ...more })
    .from(trials)
    .innerJoin(experiments, eq(experiments.id, trials.experimentId))
    .leftJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
    .leftJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(user, eq(user.id, trials.wizardId))
    .leftJoin(creator, eq(creator.id, trials.createdBy))
    .where(where);
}

export const trialsRouter = router({
  liveNow,
  // wizardId: omitted → the creator runs it; null → unassigned, the first wizard to start it claims it.
  create: studyProcedure(
    "trial.create",
    "version",
    z.object({ versionId: id, participantId: id.nullable().default(null), wizardId: id.nullable().optional() }),
  ).mutation(async ({ ctx, input }) => {
    const { studyId, row: version } = ctx;
    await assertRunsTrials(ctx.db, studyId);
    if (input.participantId) await assertMayTakePart(ctx.db, input.participantId, studyId);
    const wizardId = input.wizardId === undefined ? ctx.user.id : input.wizardId;
    if (wizardId !== null) await assertWizardOf(ctx.db, studyId, wizardId);
    const [row] = await ctx.db
      .insert(trials)
      .values({
        studyId,
        experimentId: version.experimentId,
        versionId: version.id,
        participantId: input.participantId,
        wizardId,
        createdBy: ctx.user.id,
      })
      .returning();
    return ctx.blinding.conditionsHidden ? blindTrial(row!) : row!;
  }),

  /**
   * A rehearsal runs the current draft (no published version needed), marked as rehearsal everywhere;
   * "as" a condition of this experiment, it runs that condition's variants (frozen so into its snapshot).
   */
  rehearse: studyProcedure(
    "trial.create",
    "experiment",
    z.object({ experimentId: id, condition: text("Condition", 200).optional() }),
  ).mutation(async ({ ctx, input }) => {
    const design = await loadDesign(ctx.db, ctx.row.id);
    if (design.steps.length === 0)
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: "This experiment has no steps yet: add at least one before rehearsing.",
      });
    if (input.condition !== undefined) await assertConditionOf(ctx.db, design.id, input.condition);
    const [row] = await ctx.db
      .insert(trials)
      .values({
        studyId: design.studyId,
        experimentId: design.id,
        isRehearsal: true,
        rehearsalSnapshot: inCondition(snapshotOf(design), input.condition ?? null),
        wizardId: ctx.user.id,
        createdBy: ctx.user.id,
      })
      .returning();
    return row!;
  }),

  list: studyProcedure("trial.read", "study", z.object({ studyId: id })).query(async ({ ctx }) => {
    // Scores are results: only for those who may read the data, and not under a results blind.
    const showScores = studyRoleMay(ctx.studyRole, "data.read") && !ctx.blinding.resultsHidden;
    // Read with the rows, and only for those who may see them (the others' are never read).
    const rows = await trialRows(ctx.db, eq(trials.studyId, ctx.studyId), {
      scores: showScores ? questionnaireScores : sql<null>`null`,
    }).orderBy(desc(trials.createdAt));
    // The scores the instrument publishes, by their published names: no overall Godspeed score.
    const published = (scores: NonNullable<(typeof rows)[number]["scores"]>) =>
      scores.flatMap((q) =>
        publishedScores(q.instrument, q.score as Parameters<typeof publishedScores>[1]).map((s) => ({
          name: s.subscale ? `${q.name} · ${s.subscale}` : q.name,
          score: s.value,
        })),
      );
    const shown = rows.map((r) => ({ ...r, scores: published(r.scores ?? []) }));
    return ctx.blinding.conditionsHidden ? shown.map(blindTrial) : shown;
  }),

  /** The trial's event log in order, as the fold reads it (seq, time since t0, body): what the analysis page folds. */
  events: studyProcedure(
    "data.read",
    "trial",
    z.object({ trialId: id, afterSeq: z.number().int().min(0).default(0) }),
  ).query(async ({ ctx, input }) => {
    await assertNotWithdrawn(ctx.db, ctx.row.id);
    return trialLog(ctx.db, ctx.row.id, input.afterSeq);
  }),

  /**
   * The same log as a JSON file written as it is read, for its route (/api/trials/[trialId]/events): the analysis
   * page's long logs, never parsed on the server nor held whole.
   */
  eventsJson: studyProcedure("data.read", "trial", z.object({ trialId: id })).query(async ({ ctx }) => {
    await assertNotWithdrawn(ctx.db, ctx.row.id);
    return fileAnswer(ctx, {
      filename: `trial-${ctx.row.id}-events.json`,
      contentType: "application/json; charset=utf-8",
      body: textStream(trialLogJson(ctx.db, ctx.row.id), `The log of trial ${ctx.row.id}`),
    });
  }),

  /** Annotations observers and wizards made, on the trial's clock. */
  annotations: studyProcedure("trial.read", "trial", z.object({ trialId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: annotations.id,
        relMs: annotations.relMs,
        label: annotations.label,
        note: annotations.note,
        authorId: annotations.authorId,
        authorName: user.name,
      })
      .from(annotations)
      .leftJoin(user, eq(user.id, annotations.authorId))
      .where(eq(annotations.trialId, ctx.row.id))
      .orderBy(asc(annotations.relMs)),
  ),

  /** An annotation made afterwards, while watching the recording: at any time of the trial. */
  annotate: studyProcedure(
    "annotation.create",
    "trial",
    z.object({
      trialId: id,
      relMs: z.number().finite().min(0).max(86_400_000),
      label: text("Label", 200),
      note: z.string().max(5000).default(""),
    }),
  ).mutation(async ({ ctx, input }) => {
    const [row] = await ctx.db
      .insert(annotations)
      .values({ ...input, trialId: ctx.row.id, authorId: ctx.user.id })
      .returning({ id: annotations.id });
    return row!;
  }),

  /** Its author may edit a annotation; so may the study's owner and researchers. */
  editAnnotation: studyProcedure(
    "annotation.create",
    "annotation",
    z.object({ annotationId: id, label: text("Label", 200), note: z.string().max(5000) }),
  ).mutation(async ({ ctx, input }) => {
    if (ctx.row.authorId !== ctx.user.id && !studyRoleMay(ctx.studyRole, "experiment.edit")) {
      throw new TRPCError({
        code: "FORBIDDEN",
        message: "Only the person who wrote this annotation, or the study's owner and researchers, may change it.",
      });
    }
    await ctx.db
      .update(annotations)
      .set({ label: input.label, note: input.note, updatedAt: new Date() })
      .where(eq(annotations.id, ctx.row.id));
    return { edited: ctx.row.id };
  }),

  /** The trial as a file: events or robot samples as tidy CSV, the full record (protocol embedded) as JSON, ELAN or MCAP. */
  export: studyProcedure(
    "data.read",
    "trial",
    z.object({
      trialId: id,
      format: z.enum(["csv", "json", "eaf", "samples", "mcap", "codes"], {
        error: "must be csv, json, eaf, samples, mcap or codes",
      }),
    }),
  ).query(async ({ ctx, input }) => {
    await assertNotWithdrawn(ctx.db, ctx.row.id);
    return fileAnswer(ctx, await trialFile(ctx.db, ctx.row.id, input.format));
  }),

  /** Robot state logged during the trial, in time order. */
  samples: studyProcedure(
    "data.read",
    "trial",
    z.object({
      trialId: id,
      topic: z.string().max(200).optional(),
      limit: z.number().int().min(1).max(500_000).default(200_000),
      // For a chart: at most this many samples, the first of each equal slice of time.
      maxPoints: z.number().int().min(10).max(20_000).optional(),
    }),
  ).query(async ({ ctx, input }) => {
    await assertNotWithdrawn(ctx.db, ctx.row.id);
    const where = and(
      eq(trialSamples.trialId, ctx.row.id),
      input.topic ? eq(trialSamples.topic, input.topic) : undefined,
    );
    if (input.maxPoints) {
      // Thinned in the database: an hour at 50 Hz is 180,000 rows, a chart needs a few thousand.
      const [{ last }] = (await ctx.db
        .select({ last: sql<number | null>`max(${trialSamples.relMs})` })
        .from(trialSamples)
        .where(where)) as [{ last: number | null }];
      // A number we computed, written into the SQL as a literal, as each slice's bounds and test read it.
      const perMs = sql.raw(String(input.maxPoints / Math.max(1, Number(last ?? 0) + 1)));
      // Slice k holds the samples whose floor(relMs × perMs) is k; its first is found through the index on
      // (trial, topic, time) within the slice's bounds (widened by a thousandth of a slice against rounding),
      // so an hour's 180,000 samples cost a few thousand lookups, not a sort of them all.
      const rows = await ctx.db.execute<{ topic: string; rel_ms: number; data: unknown }>(sql`
        select first.topic, first.rel_ms, first.data
        from generate_series(0, ${input.maxPoints - 1}) as slice(k)
        cross join lateral (
          select ${trialSamples.topic}, ${trialSamples.relMs}, ${trialSamples.data} from ${trialSamples}
          where ${where}
            and ${trialSamples.relMs} >= (slice.k - 0.001) / ${perMs} and ${trialSamples.relMs} < (slice.k + 1.001) / ${perMs}
            and floor(${trialSamples.relMs} * ${perMs}) = slice.k
          order by ${trialSamples.relMs} limit 1
        ) as first
        order by slice.k`);
      return rows.map((r) => ({ topic: r.topic, relMs: r.rel_ms, data: r.data }));
    }
    return ctx.db
      .select({ topic: trialSamples.topic, relMs: trialSamples.relMs, data: trialSamples.data })
      .from(trialSamples)
      .where(where)
      .orderBy(asc(trialSamples.relMs))
      .limit(input.limit);
  }),

  /** A short-lived, single-use pass to the trial runtime's socket: who and which trial, nothing more (the runtime looks up my role itself). */
  socketToken: studyProcedure("trial.read", "trial", z.object({ trialId: id })).mutation(({ ctx }) => ({
    url: ctx.runtimeUrl,
    token: signSocketToken({ userId: ctx.user.id, trialId: ctx.row.id }, ctx.secret),
  })),

  get: studyProcedure("trial.read", "trial", z.object({ trialId: id })).query(async ({ ctx }) => {
    // Three reads at once, each by the trial's id: its row with its protocol, its condition, its robot's names.
    const [[row], condition, names] = await Promise.all([
      trialRows(ctx.db, eq(trials.id, ctx.row.id), {
        protocol: sql`coalesce(${experimentVersions.snapshot}, ${trials.rehearsalSnapshot})`.mapWith(
          trials.rehearsalSnapshot,
        ),
      }),
      conditionOfTrial(ctx.db, ctx.row.id),
      // The library's names of the robot's own actions (for actions without a label) and of its events.
      trialPluginNames(ctx.db, ctx.row.id),
    ]);
    // The protocol as this trial runs it: its condition's variants (a rehearsal's were frozen as it began).
    const protocol = row!.protocol && inCondition(row!.protocol, row!.isRehearsal ? null : condition);
    const trial = { ...row!, studyId: ctx.studyId, protocol, ...names, myRole: ctx.studyRole };
    return ctx.blinding.conditionsHidden ? blindTrial(trial) : trial;
  }),
});

/** A rehearsal "as" a condition names one of this study's conditions that run this experiment. */
async function assertConditionOf(db: Parameters<typeof conditionOfTrial>[0], experimentId: string, name: string) {
  const [own] = await db
    .select({ id: conditions.id })
    .from(conditions)
    .where(and(eq(conditions.experimentId, experimentId), eq(conditions.name, name)));
  if (!own)
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: `Please correct: condition: "${name}" is not a condition of this study that runs this experiment`,
    });
}
