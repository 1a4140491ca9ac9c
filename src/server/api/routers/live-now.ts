// Trials running now in the studies the caller belongs to: the dashboard's
// "live now" list, one click from watching. Membership is the join itself;
// each row is blinded by the caller's own role in its study.
import { and, desc, eq, inArray } from "drizzle-orm";
import { alias } from "drizzle-orm/pg-core";
import { BLINDED_NAME, blindingFor } from "@/core/studies/blinding";
import { readSettings, shownTitle } from "@/core/studies/settings";
import { LIVE_STATUSES } from "@/core/trial/types";
import { experiments, participants, studies, studyMembers, trials, user } from "@/store/schema";
import { guarded } from "../trpc";

const wizard = alias(user, "wizard");

export const liveNow = guarded("account.read").query(async ({ ctx }) => {
  const rows = await ctx.db
    .select({
      trialId: trials.id,
      status: trials.status,
      isRehearsal: trials.isRehearsal,
      t0: trials.t0,
      studyId: studies.id,
      studyTitle: studies.title,
      studyStatus: studies.status,
      settings: studies.settings,
      role: studyMembers.role,
      experimentName: experiments.name,
      participantCode: participants.code,
      wizardName: wizard.name,
    })
    .from(trials)
    .innerJoin(studyMembers, and(eq(studyMembers.studyId, trials.studyId), eq(studyMembers.userId, ctx.user.id)))
    .innerJoin(studies, eq(studies.id, trials.studyId))
    .innerJoin(experiments, eq(experiments.id, trials.experimentId))
    .leftJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(wizard, eq(wizard.id, trials.wizardId))
    .where(inArray(trials.status, [...LIVE_STATUSES]))
    .orderBy(desc(trials.t0));
  return rows.map(({ settings, studyStatus, role, ...row }) => {
    const read = readSettings(settings);
    const hidden = blindingFor(role, read, studyStatus).conditionsHidden;
    return {
      ...row,
      myRole: role,
      studyTitle: shownTitle(row.studyTitle, read, hidden),
      experimentName: hidden ? BLINDED_NAME : row.experimentName,
    };
  });
});
