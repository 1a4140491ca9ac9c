// Publishing freezes the draft into an immutable, numbered, hashed version.
import { TRPCError } from "@trpc/server";
import { desc, eq, getTableColumns, sql } from "drizzle-orm";
import { validating } from "@/core/designer/validate";
import { hashing } from "@/core/protocol/canonical";
import { snapshotOf } from "@/core/protocol/snapshot";
import type { Database } from "@/store/client";
import { actions, experimentVersions, experiments, pluginDocuments, steps } from "@/store/schema";
import { knownPlugin } from "@/robots/catalog";
import { soundProblems } from "../media/audio";
import { sliced } from "@/store/sliced";
import { loadDesign } from "./design";
import { inTurn, LARGE_DESIGN } from "./turns";

// The snapshot is not read back: it is the one in hand, 5 MB of text to parse again for the largest design.
const { snapshot: _, ...columnsButSnapshot } = getTableColumns(experimentVersions);

export async function publish(db: Database, experimentId: string, userId: string) {
  const [{ actionCount }] = (await db
    .select({ actionCount: sql<number>`count(*)::int` })
    .from(actions)
    .innerJoin(steps, eq(steps.id, actions.stepId))
    .where(eq(steps.experimentId, experimentId))) as [{ actionCount: number }];
  return inTurn(actionCount >= LARGE_DESIGN, () => publishNow(db, experimentId, userId));
}

async function publishNow(db: Database, experimentId: string, userId: string) {
  return db.transaction(async (tx) => {
    // Locks the experiment so two publishes cannot take the same number.
    await tx.select({ id: experiments.id }).from(experiments).where(eq(experiments.id, experimentId)).for("update");
    const design = await loadDesign(tx, experimentId);
    if (design.steps.length === 0) {
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: "This experiment has no steps yet: add at least one step before publishing.",
      });
    }
    // The exact plugin document the design was published against (the source
    // the experiment chose): its trials run with it, whatever is installed later.
    const known = await knownPlugin(tx, design.robotId, design.pluginSource);
    const plugin = known?.plugin;
    // The published form, made once: checked, searched for sounds and hashed as it is.
    const snapshot = snapshotOf(design);
    const draft = { ...snapshot.experiment, steps: snapshot.steps };
    const issues = await sliced(validating(draft, plugin ?? null));
    // The designer only warns of an action the robot cannot do; a version that trials run must not hold one.
    const cannot = issues.filter((i) => i.code === "unsupported_on_robot");
    if (cannot.length) {
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: `This experiment cannot be published: ${plugin?.name ?? design.robotId} cannot do ${cannot.length === 1 ? "this action" : `these ${cannot.length} actions`}. ${cannot.map((i) => `${stepOf(design.steps, i.stepId)}: ${i.message}`).join("; ")}. Replace or remove ${cannot.length === 1 ? "it" : "them"}, or choose another robot.`,
      });
    }
    const problems = issues.filter((i) => i.severity === "error");
    if (problems.length) {
      const listed = problems
        .slice(0, 5)
        .map((p) => p.message)
        .join(" ");
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: `This experiment cannot be published until ${problems.length === 1 ? "this problem is" : `these ${problems.length} problems are`} fixed: ${listed}`,
      });
    }
    const sounds = await soundProblems(tx, design.studyId, draft);
    if (sounds.length)
      throw new TRPCError({ code: "BAD_REQUEST", message: `This experiment cannot be published: ${sounds.join(" ")}` });
    if (known) {
      await tx
        .insert(pluginDocuments)
        .values({
          hash: known.hash,
          robotId: known.robotId,
          version: known.plugin.version,
          source: known.source,
          definition: known.plugin,
        })
        .onConflictDoNothing();
    }
    const canonical = await sliced(hashing(snapshot));
    const [latest] = await tx
      .select(columnsButSnapshot)
      .from(experimentVersions)
      .where(eq(experimentVersions.experimentId, experimentId))
      .orderBy(desc(experimentVersions.version))
      .limit(1);
    // The draft as last published, on the same plugin document: that version is the one to run, not a copy under
    // a new number (the seeded demo is published, and a script that publishes before each trial runs it too).
    if (latest && latest.hash === canonical.hash && latest.pluginHash === (known?.hash ?? null)) {
      return { ...latest, snapshot };
    }
    const [version] = await tx
      .insert(experimentVersions)
      .values({
        experimentId,
        version: (latest?.version ?? 0) + 1,
        // The text just hashed, so the snapshot is not written out a second time.
        snapshot: sql`${canonical.text}::jsonb`,
        hash: canonical.hash,
        robotId: design.robotId,
        pluginVersion: plugin?.version ?? null,
        pluginHash: known?.hash ?? null,
        pluginSource: known?.source ?? null,
        publishedBy: userId,
      })
      .returning(columnsButSnapshot);
    return { ...version!, snapshot };
  });
}

/** "Step 2 (Greeting)": where an action is, as the designer numbers steps. */
function stepOf(steps: Array<{ id: string; name: string }>, stepId: string | undefined): string {
  const at = steps.findIndex((s) => s.id === stepId);
  return at < 0 ? "A step" : `Step ${at + 1} (${steps[at]!.name})`;
}
