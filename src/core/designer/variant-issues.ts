// What the designer says of a design's variants, given the conditions of the
// study that run this experiment: which conditions have no variant of a varied
// action or step (they run the shared one: maybe meant, maybe forgotten), and
// which variants are for no such condition (a save refuses them).
import { lackingVariants, unknownConditions } from "../protocol/variants";
import type { DesignDraft } from "./types";
import type { DesignIssue } from "./validate";

export function variantIssues(draft: DesignDraft, conditions: readonly string[]): DesignIssue[] {
  const quoted = (names: string[]) => names.map((n) => `"${n}"`).join(", ");
  const lacking = lackingVariants(draft.steps, conditions).map(
    ({ stepId, actionId, conditions: missing }): DesignIssue => ({
      severity: "warning",
      code: "variant_missing",
      message: `${actionId ? "This action" : "This step"} varies by condition, but ${quoted(missing)} ${missing.length === 1 ? "has" : "have"} no variant of it and ${missing.length === 1 ? "runs" : "run"} the shared one.`,
      stepId,
      ...(actionId && { actionId }),
    }),
  );
  const unknown = unknownConditions(draft.steps, conditions);
  return unknown.length
    ? [
        ...lacking,
        {
          severity: "error",
          code: "variant_unknown_condition",
          message: `Variants for ${quoted(unknown)}: no condition of this study by that name runs this experiment. Remove them, or rename the condition they were for back to that name.`,
        },
      ]
    : lacking;
}
