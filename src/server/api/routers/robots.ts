// The robot registry, for administrators: each physical robot with its plugin,
// its ways in (rosbridge, SSH, HTTP), where its SSH secret is read (never the
// secret), the studies it is available to, and its live health as the
// runtime last wrote it, with what its side reported during its live trial
// (a silent topic, a refused subscription), read from that trial's log.
import { TRPCError } from "@trpc/server";
import { and, asc, eq, inArray } from "drizzle-orm";
import { z } from "zod";
import { parseSecretReference, robotSecretNames } from "@/core/robots/secrets";
import { LIVE_STATUSES } from "@/core/trial/types";
import { robotStudies, robots, studies, trialEvents, trials } from "@/store/schema";
import { audit } from "../../audit";
import { guarded, router } from "../trpc";
import { id, text } from "../validation";

const optional = (schema: z.ZodString) =>
  z.preprocess((v) => (typeof v === "string" && v.trim() === "" ? null : v), schema.nullable().default(null));

const url = (what: string, protocols: RegExp) =>
  z
    .string()
    .trim()
    .url(`${what} must be a full address`)
    .refine((v) => protocols.test(v), `${what} must start with ${protocols.source.replace(/[\^()\\]/g, "")}`);

const robotInput = z.object({
  name: text("Name", 100),
  // The plugin's robotId; null: any plugin (a stand-in such as a simulated robot).
  pluginRobotId: optional(z.string().trim().max(100)),
  rosbridgeUrl: optional(url("The rosbridge address", /^wss?:\/\//)),
  sshHost: optional(z.string().trim().max(255)),
  sshPort: z.number().int().min(1).max(65535).default(22),
  sshUser: optional(z.string().trim().max(100)),
  sshSecret: optional(
    z
      .string()
      .trim()
      .superRefine((v, ctx) => {
        const parsed = parseSecretReference(v);
        if ("error" in parsed) ctx.addIssue({ code: "custom", message: `The SSH secret ${parsed.error}` });
      }),
  ),
  httpUrl: optional(url("The HTTP address", /^https?:\/\//)),
  allStudies: z.boolean().default(false),
  studyIds: z.array(id).max(1000).default([]),
});

type RobotInput = z.infer<typeof robotInput>;

function sshComplete(input: RobotInput) {
  if (input.sshHost && !input.sshUser)
    throw new TRPCError({ code: "BAD_REQUEST", message: "SSH user: give the user to log in as on the robot." });
}

async function nameFree(db: Parameters<typeof audit>[0], name: string, except?: string) {
  const [taken] = await db.select({ id: robots.id }).from(robots).where(eq(robots.name, name));
  if (taken && taken.id !== except)
    throw new TRPCError({ code: "CONFLICT", message: `A robot is already registered as "${name}".` });
}

async function setStudies(db: Parameters<typeof audit>[0], robotId: string, studyIds: string[]) {
  const unique = [...new Set(studyIds)];
  const known = unique.length
    ? await db.select({ id: studies.id }).from(studies).where(inArray(studies.id, unique))
    : [];
  if (known.length !== unique.length)
    throw new TRPCError({ code: "BAD_REQUEST", message: "Studies: one of the chosen studies no longer exists." });
  await db.delete(robotStudies).where(eq(robotStudies.robotId, robotId));
  if (unique.length) await db.insert(robotStudies).values(unique.map((studyId) => ({ robotId, studyId })));
}

/** A robot's reported problems shown at most: the admin's table is a glance, the trial's log has them all. */
const PROBLEMS_SHOWN = 3;

const details = ({ studyIds, ...input }: RobotInput) => ({ ...input, studies: studyIds.length });

export const robotsRouter = router({
  list: guarded("admin.robots").query(async ({ ctx }) => {
    const rows = await ctx.db.select().from(robots).orderBy(asc(robots.name));
    const availability = await ctx.db
      .select({ robotId: robotStudies.robotId, studyId: studies.id, title: studies.title })
      .from(robotStudies)
      .innerJoin(studies, eq(studies.id, robotStudies.studyId))
      .orderBy(asc(studies.title));
    const live = await ctx.db
      .select({ robotId: trials.assignedRobotId, trialId: trials.id })
      .from(trials)
      .where(inArray(trials.status, [...LIVE_STATUSES]));
    const driven = new Set(live.map((l) => l.robotId));
    const reported = live.length
      ? await ctx.db
          .select({ trialId: trialEvents.trialId, payload: trialEvents.payload })
          .from(trialEvents)
          .where(
            and(
              inArray(
                trialEvents.trialId,
                live.map((l) => l.trialId),
              ),
              eq(trialEvents.type, "robot.problem"),
            ),
          )
          .orderBy(asc(trialEvents.seq))
      : [];
    /** The last few different things the robot's side reported during its live trial, oldest first. */
    const problemsOf = (robotId: string) => {
      const trialIds = new Set(live.filter((l) => l.robotId === robotId).map((l) => l.trialId));
      const texts = reported.flatMap((r) => (trialIds.has(r.trialId) ? [(r.payload as { text: string }).text] : []));
      return [...new Set(texts.reverse())].slice(0, PROBLEMS_SHOWN).reverse();
    };
    return rows.map(({ seededFrom, ...robot }) => ({
      ...robot,
      seeded: seededFrom !== null,
      inLiveTrial: driven.has(robot.id),
      problems: problemsOf(robot.id),
      studies: availability.filter((a) => a.robotId === robot.id).map(({ studyId, title }) => ({ id: studyId, title })),
    }));
  }),

  /** The variables a robot's SSH password may be read from, as this server has them: names, never values. */
  secretNames: guarded("admin.robots").query(() => robotSecretNames(Object.keys(process.env))),

  /** Every study, for choosing where a robot is available. */
  studies: guarded("admin.robots").query(({ ctx }) =>
    ctx.db.select({ id: studies.id, title: studies.title }).from(studies).orderBy(asc(studies.title)),
  ),

  register: guarded("admin.robots")
    .input(robotInput)
    .mutation(async ({ ctx, input }) => {
      sshComplete(input);
      return ctx.db.transaction(async (tx) => {
        await nameFree(tx, input.name);
        const { studyIds, ...fields } = input;
        const [row] = await tx.insert(robots).values(fields).returning();
        await setStudies(tx, row!.id, studyIds);
        await audit(tx, { actorId: ctx.user.id, action: "robot.register", target: row!.id, details: details(input) });
        return row!;
      });
    }),

  update: guarded("admin.robots")
    .input(robotInput.extend({ robotId: id }))
    .mutation(async ({ ctx, input: { robotId, ...input } }) => {
      sshComplete(input);
      return ctx.db.transaction(async (tx) => {
        await nameFree(tx, input.name, robotId);
        const { studyIds, ...fields } = input;
        const [row] = await tx.update(robots).set(fields).where(eq(robots.id, robotId)).returning();
        if (!row) throw new TRPCError({ code: "NOT_FOUND", message: "No such robot: it may have been removed." });
        await setStudies(tx, robotId, studyIds);
        await audit(tx, { actorId: ctx.user.id, action: "robot.update", target: robotId, details: details(input) });
        return row;
      });
    }),

  remove: guarded("admin.robots")
    .input(z.object({ robotId: id }))
    .mutation(async ({ ctx, input }) => {
      const [driving] = await ctx.db
        .select({ id: trials.id })
        .from(trials)
        .where(and(eq(trials.assignedRobotId, input.robotId), inArray(trials.status, [...LIVE_STATUSES])));
      if (driving)
        throw new TRPCError({
          code: "CONFLICT",
          message: "This robot is being driven by a live trial: remove it once that trial has ended.",
        });
      const [row] = await ctx.db.delete(robots).where(eq(robots.id, input.robotId)).returning({ name: robots.name });
      if (!row) throw new TRPCError({ code: "NOT_FOUND", message: "No such robot: it may have been removed." });
      await audit(ctx.db, {
        actorId: ctx.user.id,
        action: "robot.remove",
        target: input.robotId,
        details: { name: row.name },
      });
      return { removed: input.robotId };
    }),
});
