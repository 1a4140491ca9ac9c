import { TRPCError } from "@trpc/server";
import { and, asc, eq, isNotNull, sql } from "drizzle-orm";
import { z } from "zod";
import { assign, strategyFor } from "@/core/studies/assignment";
import { readSettings } from "@/core/studies/settings";
import { audit } from "../../audit";
import { conditions, experiments, participants, studies } from "@/store/schema";
import { qualified } from "@/store/qualified";
import { router, studyProcedure } from "../trpc";
import { id, text } from "../validation";

export const conditionsRouter = router({
  list: studyProcedure("experiment.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: conditions.id,
        name: conditions.name,
        description: conditions.description,
        experimentId: conditions.experimentId,
        experimentName: experiments.name,
        robotId: experiments.robotId,
        participantCount: sql<number>`(select count(*)::int from ${participants} where ${participants.conditionId} = ${qualified(conditions.id)})`,
      })
      .from(conditions)
      .innerJoin(experiments, eq(experiments.id, conditions.experimentId))
      .where(eq(conditions.studyId, ctx.studyId))
      .orderBy(asc(conditions.name)),
  ),

  // The experiment is checked to be this study's by the middleware, like every id of the input.
  create: studyProcedure(
    "experiment.edit",
    "study",
    z.object({
      studyId: id,
      name: text("Condition name", 200),
      description: z.string().max(2000).default(""),
      experimentId: id,
    }),
  ).mutation(async ({ ctx, input }) => {
    const [row] = await ctx.db
      .insert(conditions)
      .values({ ...input, studyId: ctx.studyId })
      .returning()
      .catch((e: { cause?: { code?: string } }) => {
        if (e.cause?.code === "23505")
          throw new TRPCError({
            code: "CONFLICT",
            message: `This study already has a condition called ${input.name}.`,
          });
        throw e;
      });
    return row!;
  }),

  /** Assigns a participant by the study's strategy, on the server, recording seed and position. */
  assign: studyProcedure(
    "participant.manage",
    "participant",
    z.object({ participantId: id, conditionId: id.optional() }),
  ).mutation(({ ctx, input }) =>
    ctx.db.transaction(async (tx) => {
      // Read again under the study's lock below: another assignment may have just happened.
      const [participant] = await tx.select().from(participants).where(eq(participants.id, ctx.row.id));
      // Serialises assignments in a study, so two can never take the same position.
      const [study] = await tx.select().from(studies).where(eq(studies.id, participant!.studyId)).for("update");
      if (participant!.assignment)
        throw new TRPCError({
          code: "CONFLICT",
          message: `${participant!.code} is already assigned; assignments are never redrawn.`,
        });
      const list = await tx
        .select()
        .from(conditions)
        .where(eq(conditions.studyId, study!.id))
        .orderBy(asc(conditions.createdAt), asc(conditions.id));
      const settings = readSettings(study!.settings).assignment;
      const strategy = strategyFor(settings, participant!.demographics as Record<string, unknown>);
      const stratum = strategy.kind === "stratified" ? strategy.stratum : undefined;
      // A stratum's position counts only the participants assigned in it (the stratum they had then).
      const [{ position }] = (await tx
        .select({ position: sql<number>`count(*)::int` })
        .from(participants)
        .where(
          and(
            eq(participants.studyId, study!.id),
            isNotNull(participants.assignment),
            stratum === undefined ? undefined : sql`${participants.assignment}->>'stratum' = ${stratum}`,
          ),
        )) as [{ position: number }];
      const seed = settings.seed ?? "";
      const fixed = list.find((c) => c.id === input.conditionId)?.name;
      let result: ReturnType<typeof assign>;
      try {
        result = assign(
          strategy,
          list.map((c) => c.name),
          seed,
          position,
          fixed,
        );
      } catch (error) {
        throw new TRPCError({ code: "BAD_REQUEST", message: (error as Error).message });
      }
      const byName = (name: string) => list.find((c) => c.name === name)!.id;
      const record = {
        strategy: settings.strategy,
        perCondition: settings.perCondition,
        ...(stratum === undefined ? {} : { stratifyBy: settings.stratifyBy, stratum }),
        seed,
        position,
        at: new Date().toISOString(),
      };
      const [row] = await tx
        .update(participants)
        .set(
          "condition" in result
            ? { conditionId: byName(result.condition), assignment: record }
            : { conditionOrder: result.order.map(byName), conditionId: byName(result.order[0]!), assignment: record },
        )
        .where(eq(participants.id, participant!.id))
        .returning();
      await audit(tx, {
        actorId: ctx.user.id,
        studyId: study!.id,
        action: "participant.assign",
        target: participant!.id,
        details: { ...record, result },
      });
      return row!;
    }),
  ),
});
