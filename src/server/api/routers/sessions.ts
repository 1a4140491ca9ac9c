// A study's sessions: participant, condition, planned time and wizard. The
// wizard's "My sessions" lists theirs and starts the right trial with one
// click; under a blind, nothing here names the condition to a wizard.
import { assertWizardOf } from "../../studies/wizard-gate";
import { TRPCError } from "@trpc/server";
import { and, asc, desc, eq, inArray, isNull, or, sql } from "drizzle-orm";
import { z } from "zod";
import { runsAssigned, studyRoleMay } from "@/core/access/policy";
import { blindingFor } from "@/core/studies/blinding";
import { readSettings, shownTitle } from "@/core/studies/settings";
import { OPEN_STATUSES } from "@/core/trial/types";
import {
  conditions,
  experimentVersions,
  participants,
  sessions,
  studies,
  studyMembers,
  trials,
  user,
} from "@/store/schema";
import { assertMayTakePart } from "../../studies/consent-gate";
import { assertRunsTrials } from "../../studies/status-gate";
import { guarded, router, studyProcedure } from "../trpc";
import { id } from "../validation";

const plannedAt = z.coerce.date({ error: "must be a date and time" });

function columns(hideConditions: boolean) {
  return {
    id: sessions.id,
    studyId: sessions.studyId,
    plannedAt: sessions.plannedAt,
    participantId: sessions.participantId,
    participantCode: participants.code,
    conditionName: hideConditions ? sql<string | null>`null` : sql<string | null>`${conditions.name}`,
    wizardId: sessions.wizardId,
    wizardName: user.name,
    trialId: sessions.trialId,
    trialStatus: trials.status,
  };
}

export const sessionsRouter = router({
  list: studyProcedure("participant.read", "study", z.object({ studyId: id })).query(async ({ ctx }) => {
    const rows = await ctx.db
      .select(columns(ctx.blinding.conditionsHidden))
      .from(sessions)
      .innerJoin(participants, eq(participants.id, sessions.participantId))
      .innerJoin(conditions, eq(conditions.id, sessions.conditionId))
      .leftJoin(user, eq(user.id, sessions.wizardId))
      .leftJoin(trials, eq(trials.id, sessions.trialId))
      .where(eq(sessions.studyId, ctx.studyId))
      .orderBy(asc(sessions.plannedAt));
    // Only the Start buttons the caller may use: another wizard's session is theirs to run.
    const run = studyRoleMay(ctx.studyRole, "trial.run");
    return rows.map((r) => ({ ...r, mayRun: run && runsAssigned(ctx.studyRole, r.wizardId, ctx.user.id) }));
  }),

  /**
   * Plans a session in the participant's assigned condition; within-subject,
   * the next condition of their order that has no session yet.
   */
  schedule: studyProcedure(
    "participant.manage",
    "participant",
    z.object({ participantId: id, plannedAt, wizardId: id }),
  ).mutation(async ({ ctx, input }) => {
    const p = ctx.row;
    if (!p.conditionId)
      throw new TRPCError({
        code: "PRECONDITION_FAILED",
        message: `${p.code} has no condition yet: assign them first.`,
      });
    await assertWizardOf(ctx.db, p.studyId, input.wizardId);
    const planned = (
      await ctx.db.select({ c: sessions.conditionId }).from(sessions).where(eq(sessions.participantId, p.id))
    ).map((r) => r.c);
    const order = Array.isArray(p.conditionOrder) ? (p.conditionOrder as string[]) : [p.conditionId];
    const conditionId = order.find((c) => !planned.includes(c));
    if (!conditionId)
      throw new TRPCError({
        code: "CONFLICT",
        message: `${p.code} already has a session for every condition they are assigned.`,
      });
    const [row] = await ctx.db
      .insert(sessions)
      .values({
        studyId: p.studyId,
        participantId: p.id,
        conditionId,
        wizardId: input.wizardId,
        plannedAt: input.plannedAt,
        createdBy: ctx.user.id,
      })
      .returning({ id: sessions.id, plannedAt: sessions.plannedAt });
    return row!;
  }),

  remove: studyProcedure("participant.manage", "session", z.object({ sessionId: id })).mutation(async ({ ctx }) => {
    if (ctx.row.trialId)
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: "This session has started: its trial is part of the study's data and stays.",
      });
    await ctx.db.delete(sessions).where(eq(sessions.id, ctx.row.id));
    return { removed: ctx.row.id };
  }),

  /** The sessions I run that are not finished, soonest first, across my studies. */
  mine: guarded("account.read").query(async ({ ctx }) => {
    const rows = await ctx.db
      .select({
        ...columns(false),
        studyTitle: studies.title,
        studyStatus: studies.status,
        settings: studies.settings,
        role: studyMembers.role,
      })
      .from(sessions)
      .innerJoin(studies, eq(studies.id, sessions.studyId))
      .innerJoin(studyMembers, and(eq(studyMembers.studyId, sessions.studyId), eq(studyMembers.userId, ctx.user.id)))
      .innerJoin(participants, eq(participants.id, sessions.participantId))
      .innerJoin(conditions, eq(conditions.id, sessions.conditionId))
      .leftJoin(user, eq(user.id, sessions.wizardId))
      .leftJoin(trials, eq(trials.id, sessions.trialId))
      .where(
        and(
          eq(sessions.wizardId, ctx.user.id),
          or(isNull(sessions.trialId), inArray(trials.status, [...OPEN_STATUSES])),
        ),
      )
      .orderBy(asc(sessions.plannedAt));
    return rows.map(({ settings, role, studyStatus, ...row }) => {
      const read = readSettings(settings);
      const hidden = blindingFor(role, read, studyStatus).conditionsHidden;
      return {
        ...row,
        studyTitle: shownTitle(row.studyTitle, read, hidden),
        conditionName: hidden ? null : row.conditionName,
      };
    });
  }),

  /** Starts the session's trial on its condition's latest published version, or reopens the one it started. */
  start: studyProcedure("trial.run", "session", z.object({ sessionId: id })).mutation(async ({ ctx }) => {
    const s = ctx.row;
    if (!runsAssigned(ctx.studyRole, s.wizardId, ctx.user.id)) {
      throw new TRPCError({ code: "FORBIDDEN", message: "This session is planned for another wizard." });
    }
    if (s.trialId) return { trialId: s.trialId };
    await assertRunsTrials(ctx.db, s.studyId);
    await assertMayTakePart(ctx.db, s.participantId, s.studyId);
    const [condition] = await ctx.db.select().from(conditions).where(eq(conditions.id, s.conditionId));
    const [version] = await ctx.db
      .select()
      .from(experimentVersions)
      .where(eq(experimentVersions.experimentId, condition!.experimentId))
      .orderBy(desc(experimentVersions.version))
      .limit(1);
    if (!version)
      throw new TRPCError({
        code: "PRECONDITION_FAILED",
        message: "This session's experiment has no published version yet: ask a researcher to publish it.",
      });
    return ctx.db
      .transaction(async (tx) => {
        const [trial] = await tx
          .insert(trials)
          .values({
            studyId: s.studyId,
            experimentId: condition!.experimentId,
            versionId: version.id,
            participantId: s.participantId,
            // Run by whoever starts it; created by whoever planned the session.
            wizardId: ctx.user.id,
            createdBy: s.createdBy ?? ctx.user.id,
          })
          .returning({ id: trials.id });
        // Only one start wins: a second click reopens the first's trial.
        const [claimed] = await tx
          .update(sessions)
          .set({ trialId: trial!.id })
          .where(and(eq(sessions.id, s.id), isNull(sessions.trialId)))
          .returning({ trialId: sessions.trialId });
        if (!claimed) tx.rollback();
        return { trialId: trial!.id };
      })
      .catch(async (error: unknown) => {
        const [again] = await ctx.db.select({ trialId: sessions.trialId }).from(sessions).where(eq(sessions.id, s.id));
        if (again?.trialId) return { trialId: again.trialId };
        throw error;
      });
  }),
});
