// Inputs of the design procedures: the parts of steps and actions a person edits.
import { z } from "zod";
import { id, text } from "../validation";

const MAX_PARAMETERS_BYTES = 64 * 1024;

export const parameters = z
  .record(z.string(), z.unknown(), { error: "must be an object of named values" })
  .refine(
    (p) => JSON.stringify(p).length <= MAX_PARAMETERS_BYTES,
    `must be smaller than ${MAX_PARAMETERS_BYTES / 1024} KB`,
  );

export const actionFields = z.object({
  type: text("Action type", 200),
  name: z.string().trim().max(200, "must be at most 200 characters").default(""),
  parameters: parameters.default({}),
  parallelGroup: z.string().trim().min(1).max(100).nullable().default(null),
});

export const stepFields = z.object({
  name: text("Step name", 200),
  description: z.string().max(5000, "must be at most 5000 characters").default(""),
});

export const experimentDetails = z.object({
  name: text("Name", 200),
  description: z.string().max(5000, "must be at most 5000 characters"),
  robotPluginId: text("Robot", 200),
});

/** A whole design, as the designer saves it: ids present are kept, absent ones are new. */
export const designInput = z.object({
  experimentId: id,
  baseRevision: z.number().int().min(0),
  details: experimentDetails.partial().optional(),
  steps: z
    .array(
      stepFields.extend({ id: id.optional(), actions: z.array(actionFields.extend({ id: id.optional() })).max(500) }),
    )
    .max(500),
});

export type DesignInput = z.infer<typeof designInput>;
