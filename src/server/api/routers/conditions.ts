import { TRPCError } from "@trpc/server";
import { and, asc, eq, isNotNull, sql } from "drizzle-orm";
import { z } from "zod";
import { assign, type Strategy } from "@/core/studies/assignment";
import { readSettings } from "@/core/studies/settings";
import { audit } from "../../audit";
import { conditions, experiments, participants, studies } from "../../db/schema";
import { qualified } from "../../db/qualified";
import { guarded, router } from "../trpc";
import { id, text } from "../validation";

export const conditionsRouter = router({
  list: guarded("experiment.read")
    .input(z.object({ studyId: id }))
    .query(({ ctx, input }) =>
      ctx.db
        .select({
          id: conditions.id,
          name: conditions.name,
          description: conditions.description,
          experimentId: conditions.experimentId,
          experimentName: experiments.name,
          robotPluginId: experiments.robotPluginId,
          participantCount: sql<number>`(select count(*)::int from ${participants} where ${participants.conditionId} = ${qualified(conditions.id)})`,
        })
        .from(conditions)
        .innerJoin(experiments, eq(experiments.id, conditions.experimentId))
        .where(eq(conditions.studyId, input.studyId))
        .orderBy(asc(conditions.name)),
    ),

  create: guarded("experiment.edit")
    .input(z.object({ studyId: id, name: text("Condition name", 200), description: z.string().max(2000).default(""), experimentId: id }))
    .mutation(async ({ ctx, input }) => {
      const [experiment] = await ctx.db.select().from(experiments).where(and(eq(experiments.id, input.experimentId), eq(experiments.studyId, input.studyId)));
      if (!experiment) throw new TRPCError({ code: "BAD_REQUEST", message: "Please correct: experimentId: choose an experiment of this study" });
      const [row] = await ctx.db
        .insert(conditions)
        .values(input)
        .returning()
        .catch((e: { cause?: { code?: string } }) => {
          if (e.cause?.code === "23505") throw new TRPCError({ code: "CONFLICT", message: `This study already has a condition called ${input.name}.` });
          throw e;
        });
      return row!;
    }),

  delete: guarded("experiment.edit")
    .input(z.object({ conditionId: id }))
    .mutation(async ({ ctx, input }) => {
      const [used] = await ctx.db.select({ id: participants.id }).from(participants).where(eq(participants.conditionId, input.conditionId)).limit(1);
      if (used) throw new TRPCError({ code: "BAD_REQUEST", message: "Participants are assigned to this condition; it must stay for their records." });
      await ctx.db.delete(conditions).where(eq(conditions.id, input.conditionId));
      return { deleted: input.conditionId };
    }),

  /** Assigns a participant by the study's strategy, on the server, recording seed and position. */
  assign: guarded("participant.manage")
    .input(z.object({ participantId: id, conditionId: id.optional() }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [participant] = await tx.select().from(participants).where(eq(participants.id, input.participantId));
        // Serialises assignments in a study, so two can never take the same position.
        const [study] = await tx.select().from(studies).where(eq(studies.id, participant!.studyId)).for("update");
        if (participant!.assignment) throw new TRPCError({ code: "CONFLICT", message: `${participant!.code} is already assigned; assignments are never redrawn.` });
        const list = await tx.select().from(conditions).where(eq(conditions.studyId, study!.id)).orderBy(asc(conditions.createdAt), asc(conditions.id));
        const settings = readSettings(study!.settings).assignment;
        const strategy: Strategy = settings.strategy === "balanced" ? { kind: "balanced", perCondition: settings.perCondition } : { kind: settings.strategy };
        const [{ position }] = (await tx
          .select({ position: sql<number>`count(*)::int` })
          .from(participants)
          .where(and(eq(participants.studyId, study!.id), isNotNull(participants.assignment)))) as [{ position: number }];
        const seed = settings.seed ?? "";
        const fixed = list.find((c) => c.id === input.conditionId)?.name;
        let result;
        try {
          result = assign(strategy, list.map((c) => c.name), seed, position, fixed);
        } catch (error) {
          throw new TRPCError({ code: "BAD_REQUEST", message: (error as Error).message });
        }
        const byName = (name: string) => list.find((c) => c.name === name)!.id;
        const record = { strategy: settings.strategy, perCondition: settings.perCondition, seed, position, at: new Date().toISOString() };
        const [row] = await tx
          .update(participants)
          .set("condition" in result ? { conditionId: byName(result.condition), assignment: record } : { conditionOrder: result.order.map(byName), conditionId: byName(result.order[0]!), assignment: record })
          .where(eq(participants.id, participant!.id))
          .returning();
        await audit(tx, { actorId: ctx.user.id, studyId: study!.id, action: "participant.assign", target: participant!.id, details: { ...record, result } });
        return row!;
      }),
    ),
});
