"use client";
// A time limit in the designer: how many seconds, and where the trial goes
// when they run out. Empty seconds: no limit. Shared by a step ("the step may
// last …") and a Record answer ("no answer in …").
import type { TimeLimit } from "@/core/protocol/document";
import type { DesignDraft } from "@/core/designer/types";
import { Field, Input } from "@/ui/field";
import { ThenField } from "./then-field";

export function TimeLimitField({
  draft,
  stepId,
  limit,
  label,
  hint,
  onChange,
}: {
  draft: DesignDraft;
  stepId: string;
  limit: TimeLimit | undefined;
  label: string;
  hint: string;
  onChange: (limit: TimeLimit | null) => void;
}) {
  const after = limit?.after ?? { to: "next" as const };
  const setSeconds = (text: string) => {
    const seconds = Number(text);
    onChange(text.trim() && seconds > 0 ? { seconds, after } : null);
  };
  return (
    <div className="space-y-2">
      <Field label={label} hint={hint}>
        {(p) => (
          <Input
            {...p}
            type="number"
            min={1}
            max={3600}
            value={limit?.seconds ?? ""}
            placeholder="No limit"
            onChange={(e) => setSeconds(e.target.value)}
          />
        )}
      </Field>
      {limit && (
        <ThenField
          draft={draft}
          stepId={stepId}
          after={limit.after}
          label="When the time runs out"
          hint="Where the trial goes; the wizard can always act before."
          onChange={(after) => onChange({ ...limit, after })}
        />
      )}
    </div>
  );
}
