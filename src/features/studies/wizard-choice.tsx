"use client";
// Who runs a new trial: whoever starts it first (the default: they are then
// recorded as its wizard), the researcher themself, or one named member who
// may run trials.
import { useQuery } from "@tanstack/react-query";
import { studyRoleMay } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Field, NativeSelect } from "@/ui/field";

export type WizardChoiceValue = "me" | "any" | (string & {});

/** trials.create's wizardId: omitted for me, null for anyone, else the member's id. */
export const wizardIdOf = (choice: WizardChoiceValue) =>
  choice === "me" ? undefined : choice === "any" ? null : choice;

export function WizardChoice({
  studyId,
  value,
  onChange,
}: {
  studyId: string;
  value: WizardChoiceValue;
  onChange: (v: WizardChoiceValue) => void;
}) {
  const trpc = useTRPC();
  const me = useQuery(trpc.account.me.queryOptions());
  const members = useQuery(trpc.members.list.queryOptions({ studyId }));
  // Wizards first: they run most trials. "Me" is already a choice of its own.
  const others = (members.data ?? [])
    .filter((m) => studyRoleMay(m.role, "trial.run") && m.userId !== me.data?.id)
    .sort((a, b) => Number(b.role === "wizard") - Number(a.role === "wizard"));
  return (
    <Field label="Wizard" hint={value === "any" ? "Whoever starts it is recorded as its wizard." : undefined}>
      {(p) => (
        <NativeSelect {...p} value={value} onChange={(e) => onChange(e.target.value)}>
          <option value="any">Any wizard (the first to start it)</option>
          <option value="me">Me</option>
          {others.map((m) => (
            <option key={m.userId} value={m.userId}>
              {m.name} ({m.role})
            </option>
          ))}
        </NativeSelect>
      )}
    </Field>
  );
}
