// Experiment files in and out of a study: a lab shares a protocol with
// another lab as one file. The format lives in the core (exchange.ts).
import { TRPCError } from "@trpc/server";
import { exportExperiment, importExperiment } from "@/core/designer/exchange";
import { draftFrom } from "@/core/designer/model";
import type { Database } from "@/store/client";
import { actions, experiments, steps } from "@/store/schema";
import { fileSlug } from "../file-slug";
import { loadDesign } from "./design";

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
  const draft = result.draft;
  return db.transaction(async (tx) => {
    const [experiment] = await tx
      .insert(experiments)
      .values({
        studyId,
        name: draft.name,
        description: draft.description,
        robotId: draft.robotId,
        updatedBy: userId,
      })
      .returning();
    const stepRows = draft.steps.map((s, position) => ({
      id: s.id,
      experimentId: experiment!.id,
      position,
      name: s.name,
      description: s.description,
    }));
    const actionRows = draft.steps.flatMap((s) =>
      s.actions.map((a, position) => ({
        id: a.id,
        stepId: s.id,
        position,
        type: a.type,
        name: a.name,
        parameters: a.parameters,
        parallelGroup: a.parallelGroup,
      })),
    );
    if (stepRows.length) await tx.insert(steps).values(stepRows);
    if (actionRows.length) await tx.insert(actions).values(actionRows);
    return loadDesign(tx, experiment!.id);
  });
}
