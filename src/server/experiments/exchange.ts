// Experiment files in and out of a study: a lab shares a protocol with
// another lab as one file, and a copy within a study is made the same way.
// The format lives in the core (exchange.ts).
import { TRPCError } from "@trpc/server";
import { exportExperiment, importExperiment } from "@/core/designer/exchange";
import { draftFrom } from "@/core/designer/model";
import type { DesignDraft } from "@/core/designer/types";
import type { Database } from "@/store/client";
import { experiments } from "@/store/schema";
import { fileSlug } from "../file-slug";
import { insertSteps, loadDesign } from "./design";

export async function exportFile(db: Database, experimentId: string) {
  const design = await loadDesign(db, experimentId);
  return {
    fileName: `${fileSlug(design.name, "experiment")}.hristudio-experiment.json`,
    text: exportExperiment(draftFrom(design)),
  };
}

/** A new experiment in the study from a file; a bad file changes nothing and says where it is wrong. */
export async function importFile(db: Database, studyId: string, text: string, userId: string) {
  const result = importExperiment(text, () => crypto.randomUUID());
  if (!result.ok) {
    const shown = result.problems.slice(0, 10).map((p) => `${p.path}: ${p.message}`);
    const more = result.problems.length > 10 ? ` (and ${result.problems.length - 10} more)` : "";
    throw new TRPCError({ code: "BAD_REQUEST", message: `This file cannot be imported. ${shown.join("; ")}${more}` });
  }
  return storeNew(db, studyId, result.draft, userId);
}

/**
 * A copy of an experiment's draft in the same study, named "… (copy)". It is
 * made the way another lab would receive it, through the experiment file, so
 * it gets fresh ids with its branches and "Then"s pointing at its own steps,
 * and nothing but the design: no versions, trials or data.
 */
export async function duplicate(db: Database, experimentId: string, userId: string) {
  const design = await loadDesign(db, experimentId);
  const copied = importExperiment(exportExperiment(draftFrom(design)), () => crypto.randomUUID());
  // An exported draft always imports: the round trip is tested byte for byte in the core.
  if (!copied.ok) throw new Error(`The experiment ${experimentId} did not survive its own export`);
  return storeNew(db, design.studyId, { ...copied.draft, name: `${design.name} (copy)`.slice(0, 200) }, userId);
}

async function storeNew(db: Database, studyId: string, draft: DesignDraft, userId: string) {
  return db.transaction(async (tx) => {
    const [experiment] = await tx
      .insert(experiments)
      .values({ studyId, name: draft.name, description: draft.description, robotId: draft.robotId, updatedBy: userId })
      .returning();
    await insertSteps(tx, experiment!.id, draft.steps);
    return loadDesign(tx, experiment!.id);
  });
}
