// Inputs of the design procedures: the experiment document (declared once in
// core/protocol/document.ts) as the designer saves it.
import { z } from "zod";
import { actionSchema, countedSteps, DESIGN_LIMITS, experimentFields, stepSchema } from "@/core/protocol/document";
import { id } from "../validation";

export const experimentDetails = experimentFields.extend({
  // Required here: a new experiment's description is a deliberate choice, even an empty one.
  description: z.string().max(DESIGN_LIMITS.description, `must be at most ${DESIGN_LIMITS.description} characters`),
});

/** A whole design, as the designer saves it: ids present are kept, absent ones are new. */
export const designInput = z.object({
  experimentId: id,
  baseRevision: z.number().int().min(0),
  details: experimentDetails.partial().optional(),
  steps: countedSteps(
    z.array(
      stepSchema.extend({
        id: id.optional(),
        actions: z.array(actionSchema.extend({ id: id.optional() })).max(DESIGN_LIMITS.actionsPerStep),
      }),
    ),
  ),
});

export type DesignInput = z.infer<typeof designInput>;
