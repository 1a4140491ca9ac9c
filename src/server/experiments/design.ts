// Reading and writing an experiment's draft design. Every write bumps the
// draft revision, so a save based on an older draft can be refused.
import { TRPCError } from "@trpc/server";
import { asc, eq, inArray, sql } from "drizzle-orm";
import type { PgTable } from "drizzle-orm/pg-core";
import type { Database } from "@/store/client";
import { actions, conditions, experiments, steps } from "@/store/schema";
import type { DesignStep } from "@/core/designer/types";
import { idsInTwoSteps, unknownConditions } from "@/core/protocol/variants";
import type { DesignInput } from "../api/routers/design-input";
import { inTurn, LARGE_DESIGN } from "./turns";

export type Tx = Parameters<Parameters<Database["transaction"]>[0]>[0];

/**
 * Steps whose actions are read in one query: at most 2,000 rows, so reading
 * the largest design is many short answers rather than one that holds the
 * server while its 50,000 rows are turned into objects.
 */
const STEPS_PER_READ = 4;

export async function loadDesign(db: Database | Tx, experimentId: string) {
  const [experiment] = await db.select().from(experiments).where(eq(experiments.id, experimentId));
  if (!experiment) throw new TRPCError({ code: "NOT_FOUND", message: "Experiment not found." });
  const stepRows = await db
    .select()
    .from(steps)
    .where(eq(steps.experimentId, experimentId))
    .orderBy(asc(steps.position));
  const actionsOf = new Map(stepRows.map((s) => [s.id, [] as Array<typeof actions.$inferSelect>]));
  for (let start = 0; start < stepRows.length; start += STEPS_PER_READ) {
    const rows = await db
      .select()
      .from(actions)
      .where(
        inArray(
          actions.stepId,
          stepRows.slice(start, start + STEPS_PER_READ).map((s) => s.id),
        ),
      )
      .orderBy(asc(actions.position));
    for (const row of rows) actionsOf.get(row.stepId)!.push(row);
  }
  return {
    ...experiment,
    // A column left null is a field left out: a design without time limits hashes as it did before them.
    steps: stepRows.map((s) => ({
      ...s,
      timeLimit: s.timeLimit ?? undefined,
      variants: s.variants ?? undefined,
      actions: actionsOf.get(s.id)!.map((a) => ({
        ...a,
        parameters: a.parameters as Record<string, unknown>,
        timeLimit: a.timeLimit ?? undefined,
        variants: a.variants ?? undefined,
      })),
    })),
  };
}

export type Design = Awaited<ReturnType<typeof loadDesign>>;

/** Marks the draft changed; with `expected`, refuses if someone saved since. */
export async function bumpRevision(tx: Tx, experimentId: string, userId: string, expected?: number) {
  const [row] = await tx
    .update(experiments)
    .set({ draftRevision: sql`${experiments.draftRevision} + 1`, updatedAt: new Date(), updatedBy: userId })
    .where(eq(experiments.id, experimentId))
    .returning({ revision: experiments.draftRevision });
  if (expected !== undefined && row!.revision !== expected + 1) {
    throw new TRPCError({
      code: "CONFLICT",
      message:
        "Someone else saved this experiment after you opened it. Reload to see their changes; yours were not saved.",
    });
  }
  return row!.revision;
}

/** Replaces the whole draft in one transaction, keeping the ids it was given. */
export function saveDesign(db: Database, input: DesignInput, userId: string) {
  const actionCount = input.steps.reduce((n, s) => n + s.actions.length, 0);
  return inTurn(actionCount >= LARGE_DESIGN, () => saveNow(db, input, userId));
}

async function saveNow(db: Database, input: DesignInput, userId: string) {
  return db.transaction(async (tx) => {
    await bumpRevision(tx, input.experimentId, userId, input.baseRevision);
    await assertVariantsOwn(tx, input);
    if (input.details && Object.keys(input.details).length) {
      const [before] = await tx
        .select({ robotId: experiments.robotId })
        .from(experiments)
        .where(eq(experiments.id, input.experimentId));
      // A chosen plugin source was a choice among the old robot's documents, not the new one's.
      const robotChanged = input.details.robotId !== undefined && input.details.robotId !== before?.robotId;
      await tx
        .update(experiments)
        .set(robotChanged ? { ...input.details, pluginSource: null } : input.details)
        .where(eq(experiments.id, input.experimentId));
    }
    const ownStepIds = new Set(
      (await tx.select({ id: steps.id }).from(steps).where(eq(steps.experimentId, input.experimentId))).map(
        (s) => s.id,
      ),
    );
    const ownActionIds = new Set(
      (
        await tx
          .select({ id: actions.id })
          .from(actions)
          .innerJoin(steps, eq(steps.id, actions.stepId))
          .where(eq(steps.experimentId, input.experimentId))
      ).map((a) => a.id),
    );
    const checkId = (given: string | undefined, own: Set<string>) => {
      if (given !== undefined && !own.has(given)) assertFreshId(given);
    };
    for (const s of input.steps) {
      checkId(s.id, ownStepIds);
      for (const a of s.actions) checkId(a.id, ownActionIds);
    }
    // Made a step at a time as they are stored, not all at once.
    function* draftSteps() {
      for (const s of input.steps)
        yield {
          ...s,
          id: s.id ?? crypto.randomUUID(),
          actions: s.actions.map((a) => ({ ...a, id: a.id ?? crypto.randomUUID() })),
        };
    }
    // Delete and re-insert under the same ids: references from branches stay valid.
    if (ownStepIds.size) await tx.delete(steps).where(eq(steps.experimentId, input.experimentId));
    await insertSteps(tx, input.experimentId, draftSteps());
    return loadDesign(tx, input.experimentId);
  });
}

/** Stores a draft's steps and actions, in order, under the ids they carry, as the steps come. */
export async function insertSteps(tx: Tx, experimentId: string, draftSteps: Iterable<DesignStep>) {
  // Rows are made a batch at a time, as they are stored, not all 50,000 at once.
  let stepRows: object[] = [];
  let actionRows: object[] = [];
  const store = async () => {
    // A batch's steps first: its actions point at them.
    await insertRows(tx, steps, STEP_COLUMNS, stepRows);
    await insertRows(tx, actions, ACTION_COLUMNS, actionRows);
    stepRows = [];
    actionRows = [];
  };
  let position = 0;
  for (const s of draftSteps) {
    stepRows.push({
      id: s.id,
      experiment_id: experimentId,
      position: position++,
      name: s.name,
      description: s.description,
      after: s.after ?? { to: "next" },
      time_limit: s.timeLimit,
      variants: s.variants,
    });
    for (const [at, a] of s.actions.entries()) {
      actionRows.push({
        id: a.id,
        step_id: s.id,
        position: at,
        type: a.type,
        name: a.name,
        parameters: a.parameters,
        parallel_group: a.parallelGroup,
        note: a.note ?? "",
        time_limit: a.timeLimit,
        variants: a.variants,
      });
    }
    if (actionRows.length < ROWS_PER_INSERT) continue;
    // A large design's batches leave PostgreSQL to others for as long as each took: everyone else's queries
    // share the server's cores with them, and the design is stored in twice the time rather than theirs.
    const began = performance.now();
    await store();
    await new Promise((resume) => setTimeout(resume, performance.now() - began));
  }
  await store();
}

/** Rows per insert (a step's actions may take one a little past it): a few milliseconds of work each. */
const ROWS_PER_INSERT = 1000;
const STEP_COLUMNS =
  "id text, experiment_id text, position integer, name text, description text, after jsonb, time_limit jsonb, variants jsonb";
const ACTION_COLUMNS =
  "id text, step_id text, position integer, type text, name text, parameters jsonb, parallel_group text, note text, time_limit jsonb, variants jsonb";

/**
 * Inserts rows (keys named as `columns`) as one JSON text that PostgreSQL
 * takes apart. Drizzle's insert of many rows takes 0.1 ms a row to build
 * while holding the server (100 ms per 1,000), and overflows the stack at 50,000.
 */
async function insertRows(tx: Tx, table: PgTable, columns: string, rows: object[]) {
  if (!rows.length) return;
  const names = columns
    .split(", ")
    .map((column) => column.split(" ")[0])
    .join(", ");
  await tx.execute(
    sql`insert into ${table} (${sql.raw(names)}) select * from jsonb_to_recordset(${JSON.stringify(rows)}::jsonb) as r(${sql.raw(columns)})`,
  );
}

/** A variant is for a condition of this study that runs this experiment: any other name would never run. */
async function assertVariantsOwn(tx: Tx, input: DesignInput) {
  const own = await tx
    .select({ name: conditions.name })
    .from(conditions)
    .where(eq(conditions.experimentId, input.experimentId));
  const unknown = unknownConditions(
    input.steps,
    own.map((c) => c.name),
  );
  const repeated = idsInTwoSteps(input.steps);
  if (repeated.length)
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: `Please correct: variants: the action ${repeated.map((id) => `"${id}"`).join(", ")} is in two steps; a step's variant needs actions of its own`,
    });
  if (unknown.length)
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: `Please correct: variants: ${unknown.map((name) => `"${name}"`).join(", ")} ${unknown.length === 1 ? "is not a condition of this study that runs" : "are not conditions of this study that run"} this experiment`,
    });
}

/** A client may name a new block's id itself (so branches can point at it), but only a fresh UUID. */
function assertFreshId(given: string) {
  if (!/^[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}$/i.test(given)) {
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: `Please correct: id: "${given}" is not an id of this experiment`,
    });
  }
}
