// Experiment files in and out of a study: a lab shares a protocol with
// another lab as one file, and a copy within a study is made the same way.
// The format lives in the core (exchange.ts).
import { TRPCError } from "@trpc/server";
import { checking, draftOf, exportExperiment, importing } from "@/core/designer/exchange";
import { draftFrom } from "@/core/designer/draft";
import type { DesignDraft, DesignStep } from "@/core/designer/types";
import type { Database } from "@/store/client";
import { experiments } from "@/store/schema";
import { fileSlug } from "../file-slug";
import { sliced } from "@/store/sliced";
import { inTurn, LARGE_FILE } from "./turns";
import { findPlugin } from "@/robots/catalog";
import { insertSteps, loadDesign, type Tx } from "./design";

export async function exportFile(db: Database, experimentId: string) {
  const design = await loadDesign(db, experimentId);
  return {
    fileName: `${fileSlug(design.name, "experiment")}.hristudio-experiment.json`,
    text: exportExperiment(draftFrom(design)),
  };
}

/**
 * A new experiment in the study from a file; a bad file changes nothing and
 * says where it is wrong. It answers with the experiment, not its steps: the
 * page opens it by its id, and the largest design is 8 MB to send back.
 */
export function importFile(db: Database, studyId: string, text: string, userId: string) {
  return inTurn(text.length >= LARGE_FILE, () => importNow(db, studyId, text, userId));
}

async function importNow(db: Database, studyId: string, text: string, userId: string) {
  const result = await sliced(checking(text));
  if (!result.ok) {
    const shown = result.problems.slice(0, 10).map((p) => `${p.path}: ${p.message}`);
    const more = result.problems.length > 10 ? ` (and ${result.problems.length - 10} more)` : "";
    throw new TRPCError({ code: "BAD_REQUEST", message: `This file cannot be imported. ${shown.join("; ")}${more}` });
  }
  return storeNew(
    db,
    studyId,
    draftOf(result.file, () => crypto.randomUUID()),
    userId,
  );
}

/**
 * A copy of an experiment's draft, in its own study ("… (copy)") or, under its
 * own name, in another. It is made the way another lab would receive it,
 * through the experiment file, so it gets fresh ids with its branches and
 * "Then"s pointing at its own steps, and nothing but the design: no versions,
 * trials or data. Who may copy from where to where is the caller's to check.
 */
export async function duplicate(db: Database | Tx, experimentId: string, userId: string, intoStudyId?: string) {
  const design = await loadDesign(db, experimentId);
  const sameStudy = intoStudyId === undefined || intoStudyId === design.studyId;
  if (!sameStudy) await assertRobotInstalled(db, design);
  const copied = await sliced(importing(exportExperiment(draftFrom(design)), () => crypto.randomUUID()));
  // An exported draft always imports: the round trip is tested byte for byte in the core.
  if (!copied.ok) throw new Error(`The experiment ${experimentId} did not survive its own export`);
  const name = sameStudy ? `${design.name} (copy)`.slice(0, 200) : design.name;
  // A copy runs the same robot's document as its original: plugins are the server's, not the study's.
  const copy = await storeNew(
    db,
    intoStudyId ?? design.studyId,
    { ...copied.draft, name },
    userId,
    design.pluginSource,
  );
  return loadDesign(db, copy.id);
}

/**
 * Robot plugins are installed for the whole server, not per study: a copy
 * into another study is refused when the robot it is for has no plugin here
 * (a repository removed since), rather than leaving a design nobody can run.
 */
async function assertRobotInstalled(db: Database | Tx, design: { name: string; robotId: string }) {
  if (await findPlugin(db, design.robotId, null)) return;
  throw new TRPCError({
    code: "PRECONDITION_FAILED",
    message: `“${design.name}” is for the robot “${design.robotId}”, whose plugin is not installed on this server: an administrator can install it under Administration → Robot plugins before it is copied.`,
  });
}

async function storeNew(
  db: Database | Tx,
  studyId: string,
  draft: Omit<DesignDraft, "steps"> & { steps: Iterable<DesignStep> },
  userId: string,
  pluginSource: string | null = null,
) {
  // Inside a larger transaction (a study from a template) this is a savepoint of it.
  return db.transaction(async (tx) => {
    const [experiment] = await tx
      .insert(experiments)
      .values({
        studyId,
        name: draft.name,
        description: draft.description,
        robotId: draft.robotId,
        pluginSource,
        updatedBy: userId,
      })
      .returning();
    await insertSteps(tx, experiment!.id, draft.steps);
    return experiment!;
  });
}
