// The analysis API's tables (src/app/api/v1): read with a personal access
// token, through the same policy, blinds and study checks as every procedure.
import { and, asc, eq, inArray } from "drizzle-orm";
import { z } from "zod";
import { STUDY_COLUMNS } from "@/core/analysis/api";
import { tableOf } from "@/core/analysis/table";
import { studyAccessOf } from "@/store/study-access";
import { studies, studyMembers } from "@/store/schema";
import {
  annotationsTable,
  answersTable,
  codesTable,
  eventsTable,
  samplesTable,
  studyEventsTable,
  trialsTable,
} from "../../analysis/tables";
import { assertNotWithdrawn } from "../../trials/withdrawn";
import { guarded, router, studyProcedure } from "../trpc";
import { id } from "../validation";

const ofStudy = z.object({ studyId: id });

export const analysisRouter = router({
  /** The studies I am a member of, only those of my token when I come with one. */
  studies: guarded("data.studies").query(async ({ ctx }) => {
    const scope = ctx.token?.studyIds;
    const rows = await ctx.db
      .select({ id: studies.id, title: studies.title, status: studies.status, role: studyMembers.role })
      .from(studies)
      .innerJoin(studyMembers, and(eq(studyMembers.studyId, studies.id), eq(studyMembers.userId, ctx.user.id)))
      .where(scope ? inArray(studies.id, [...scope]) : undefined)
      .orderBy(asc(studies.title));
    const withBlinds = await Promise.all(
      rows.map(async (s) => ({ ...s, blinding: (await studyAccessOf(ctx.db, s.id, ctx.user.id)).blinding })),
    );
    return tableOf(
      STUDY_COLUMNS,
      withBlinds.map((s) => ({
        study_id: s.id,
        title: s.title,
        status: s.status,
        role: s.role,
        results_hidden: s.blinding.resultsHidden,
      })),
    );
  }),

  trials: studyProcedure("data.read", "study", ofStudy).query(({ ctx }) => trialsTable(ctx.db, ctx.studyId)),
  events: studyProcedure("data.read", "study", ofStudy).query(({ ctx }) => studyEventsTable(ctx.db, ctx.studyId)),
  samples: studyProcedure("data.read", "study", ofStudy).query(({ ctx }) => samplesTable(ctx.db, ctx.studyId)),
  answers: studyProcedure("data.read", "study", ofStudy).query(({ ctx }) => answersTable(ctx.db, ctx.studyId)),
  annotations: studyProcedure("data.read", "study", ofStudy).query(({ ctx }) => annotationsTable(ctx.db, ctx.studyId)),
  codes: studyProcedure("data.read", "study", ofStudy).query(({ ctx }) => codesTable(ctx.db, ctx.studyId)),

  trialEvents: studyProcedure("data.read", "trial", z.object({ trialId: id })).query(async ({ ctx }) => {
    await assertNotWithdrawn(ctx.db, ctx.row.id);
    return eventsTable(ctx.db, [ctx.row.id]);
  }),
});
