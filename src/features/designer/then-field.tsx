"use client";
// Where the trial goes next, as the designer asks it: the next step, a named
// step, the end, or back to this step or an earlier one "at most K times,
// then …". Shared by a step's "Then" and a time limit's "When the time runs out".
import { type After, MAX_LOOP_TIMES, type Onward } from "@/core/protocol/document";
import type { DesignDraft } from "@/core/designer/types";
import { Field, Input, NativeSelect } from "@/ui/field";

const AGAIN = "again:";
/** A new loop's bound: "ask again, at most twice", the re-ask studies use most. */
const DEFAULT_TIMES = 2;

/**
 * The choices of where a step leads (with `loops`, the bound shown, the steps
 * it may go back to), `value` kept when it names a step that is gone.
 */
export function LeadsToOptions({
  draft,
  stepId,
  value,
  loops,
}: {
  draft: DesignDraft;
  stepId: string;
  value: string;
  loops?: number;
}) {
  const index = draft.steps.findIndex((s) => s.id === stepId);
  const following = draft.steps[index + 1];
  const options: Array<[string, string]> = [
    [
      "next",
      following ? `Go on to the next step (${following.name || `step ${index + 2}`})` : "End the trial (last step)",
    ],
    ...draft.steps.flatMap(
      (s, i): Array<[string, string]> => (s.id === stepId ? [] : [[s.id, `Go to step ${i + 1}: ${s.name}`]]),
    ),
    // On the last step "next" already ends the trial: one way to say it, unless the step says "end" itself.
    ...(following || value === "end" ? [["end", "End the trial"] as [string, string]] : []),
    // A loop goes back, never forward: a step further on is a "Go to".
    ...(loops !== undefined
      ? draft.steps.slice(0, index + 1).map((s, i): [string, string] => {
          const which = s.id === stepId ? "this step" : `step ${i + 1}: ${s.name}`;
          return [`${AGAIN}${s.id}`, `Go back to ${which}, at most ${loops === 1 ? "once" : `${loops} times`}, then …`];
        })
      : []),
  ];
  if (!options.some(([v]) => v === value)) options.push([value, "A step that is no longer in the experiment"]);
  return options.map(([v, label]) => (
    <option key={v} value={v}>
      {label}
    </option>
  ));
}

export const afterValue = (after: After | undefined) =>
  !after || after.to === "next" || after.to === "end"
    ? (after?.to ?? "next")
    : `${after.to === "again" ? AGAIN : ""}${after.stepId}`;

/** The choice `value` as an "after"; a loop keeps the bound and the way on of `loop`, the loop it was. */
export function afterOf(value: string, loop: Extract<After, { to: "again" }> | null): After {
  if (value.startsWith(AGAIN))
    return {
      to: "again",
      stepId: value.slice(AGAIN.length),
      times: loop?.times ?? DEFAULT_TIMES,
      onward: loop?.onward ?? { to: "next" },
    };
  return value === "next" || value === "end" ? { to: value } : { to: "step", stepId: value };
}

export function ThenField({
  draft,
  stepId,
  after,
  label,
  hint,
  onChange,
}: {
  draft: DesignDraft;
  stepId: string;
  after: After | undefined;
  label: string;
  hint: string;
  onChange: (after: After) => void;
}) {
  const value = afterValue(after);
  const loop = after?.to === "again" ? after : null;
  const setTimes = (text: string) => {
    const times = Number(text);
    if (loop && Number.isInteger(times) && times >= 1 && times <= MAX_LOOP_TIMES) onChange({ ...loop, times });
  };
  return (
    <div className="space-y-2">
      <Field label={label} hint={hint}>
        {(p) => (
          <NativeSelect {...p} value={value} onChange={(e) => onChange(afterOf(e.target.value, loop))}>
            <LeadsToOptions draft={draft} stepId={stepId} value={value} loops={loop?.times ?? DEFAULT_TIMES} />
          </NativeSelect>
        )}
      </Field>
      {loop && (
        <>
          <Field label="At most (times back)" hint="How many times the trial may go back before it goes on.">
            {(p) => (
              <Input
                {...p}
                type="number"
                min={1}
                max={MAX_LOOP_TIMES}
                step={1}
                value={loop.times}
                onChange={(e) => setTimes(e.target.value)}
              />
            )}
          </Field>
          <Field label="Then, after the last time" hint="Where the trial goes once it has gone back that many times.">
            {(p) => (
              <NativeSelect
                {...p}
                value={afterValue(loop.onward)}
                onChange={(e) => onChange({ ...loop, onward: afterOf(e.target.value, null) as Onward })}
              >
                <LeadsToOptions draft={draft} stepId={stepId} value={afterValue(loop.onward)} />
              </NativeSelect>
            )}
          </Field>
        </>
      )}
    </div>
  );
}
