"use client";
// The whole study described for a paper's methods section, written from its
// data as it stands now: read here, copied, or downloaded (it is in the
// study's zip too).
import { useQuery } from "@tanstack/react-query";
import { useTRPC } from "@/lib/trpc";
import { MethodsText } from "@/ui/methods-text";
import { Problem } from "@/ui/problem";
import { Spinner } from "@/ui/surface";

export function MethodsTab({ studyId }: { studyId: string }) {
  const trpc = useTRPC();
  const methods = useQuery(trpc.studies.methods.queryOptions({ studyId }));
  if (methods.isPending) return <Spinner label="Writing the study's methods text…" />;
  if (methods.error) return <Problem error={methods.error} />;
  return (
    <div className="space-y-3">
      <p className="text-sm text-slate-600">
        The study described for a paper's methods section, from its data as it stands now: design, who took part in each
        condition, assignment, blinding, the robots the trials ran on, how the conditions' protocols differ, measured
        step timings, questionnaires, coding agreement, fidelity and deviations. It changes as trials run.
      </p>
      <MethodsText methods={methods.data} />
    </div>
  );
}
