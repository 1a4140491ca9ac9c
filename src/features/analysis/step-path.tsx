"use client";
// The path the trial took, a step at a time, each with what moved the trial
// into it (the start, the wizard's next, the participant's answer, a time limit, a loop, a jump)
// and the actions the wizard skipped while there: what the protocol decided
// told apart from what the wizard did.
import { moveWords, type StepVisit } from "@/core/analysis/moves";
import { seconds } from "@/ui/format";
import { Card } from "@/ui/surface";

export function StepPath({
  visits,
  stepName,
}: {
  visits: StepVisit[];
  stepName: (stepId: string) => string | undefined;
}) {
  if (!visits.length) return null;
  return (
    <section aria-labelledby="step-path">
      <h2 id="step-path" className="mb-2 text-lg font-semibold">
        What moved the trial
      </h2>
      <Card className="p-4 text-sm">
        <ol className="list-decimal space-y-1 pl-5">
          {visits.map((v) => (
            <li key={v.seq} data-visit>
              <strong>{stepName(v.stepId) ?? v.stepId}</strong> at {seconds(v.enteredMs)}: by {moveWords(v.move)}
              {v.skipped > 0 && `; the wizard skipped ${v.skipped} of its actions`}
            </li>
          ))}
        </ol>
      </Card>
    </section>
  );
}
