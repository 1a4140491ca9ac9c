"use client";
// A time limit in the designer: how many seconds, and where the trial goes
// when they run out. Empty seconds: no limit. Shared by a step ("the step may
// last …") and a Record answer ("no answer in …").
import type { After, TimeLimit } from "@/core/protocol/document";
import type { DesignDraft } from "@/core/designer/types";
import { Field, Input, NativeSelect } from "@/ui/field";

/** The choices of where a step leads, with `value` kept when it names a step that is gone. */
export function LeadsToOptions({ draft, stepId, value }: { draft: DesignDraft; stepId: string; value: string }) {
  const index = draft.steps.findIndex((s) => s.id === stepId);
  const following = draft.steps[index + 1];
  return (
    <>
      <option value="next">
        {following ? `Go on to the next step (${following.name || `step ${index + 2}`})` : "End the trial (last step)"}
      </option>
      {draft.steps.map((s, i) =>
        s.id === stepId ? null : (
          <option key={s.id} value={s.id}>
            Go to step {i + 1}: {s.name}
          </option>
        ),
      )}
      {/* On the last step "next" already ends the trial: one way to say it, unless the step says "end" itself. */}
      {(following || value === "end") && <option value="end">End the trial</option>}
      {value !== "next" && value !== "end" && !draft.steps.some((s) => s.id === value) && (
        <option value={value}>A step that is no longer in the experiment</option>
      )}
    </>
  );
}

export const afterValue = (after: After | undefined) =>
  !after || after.to === "next" ? "next" : after.to === "end" ? "end" : after.stepId;

export const afterOf = (value: string): After =>
  value === "next" || value === "end" ? { to: value } : { to: "step", stepId: value };

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
        <Field label="When the time runs out" hint="Where the trial goes; the wizard can always act before.">
          {(p) => (
            <NativeSelect
              {...p}
              value={afterValue(limit.after)}
              onChange={(e) => onChange({ ...limit, after: afterOf(e.target.value) })}
            >
              <LeadsToOptions draft={draft} stepId={stepId} value={afterValue(limit.after)} />
            </NativeSelect>
          )}
        </Field>
      )}
    </div>
  );
}
