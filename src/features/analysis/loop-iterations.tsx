"use client";
// How the trial went round each loop of the protocol: times back out of its
// bound, whether the bound was reached, and how often each step was entered.
import type { FidelityReport } from "@/core/analysis/fidelity";
import { Card } from "@/ui/surface";

export function LoopIterations({
  report,
  stepName,
}: {
  report: FidelityReport;
  stepName: (stepId: string) => string | undefined;
}) {
  if (!report.loops.length) return null;
  const name = (stepId: string) => `“${stepName(stepId) ?? stepId}”`;
  const again = report.steps.filter((s) => s.entered > 1);
  return (
    <section aria-labelledby="loop-iterations">
      <h2 id="loop-iterations" className="mb-2 text-lg font-semibold">
        Loops
      </h2>
      <Card className="space-y-2 p-4 text-sm">
        <ul className="space-y-1">
          {report.loops.map((l) => (
            <li key={l.loop} data-loop>
              From {name(l.stepId)} back to {name(l.backToStepId)}: went back {l.taken} of at most{" "}
              {l.times === 1 ? "1 time" : `${l.times} times`};{" "}
              {l.boundReached ? "its bound was reached and the trial went on" : "its bound was not reached"}
            </li>
          ))}
        </ul>
        {again.length > 0 && (
          <p>Steps entered more than once: {again.map((s) => `${name(s.stepId)} ${s.entered} times`).join(", ")}.</p>
        )}
      </Card>
    </section>
  );
}
