"use client";
// The study's results at a glance: how consistently the wizard(s) ran the
// protocol, every finished trial's fidelity, and each step's timing across
// participants (median with its range); then the conditions compared.
import { useQuery } from "@tanstack/react-query";
import Link from "next/link";
import type { StudySummary } from "@/core/analysis/study-summary";
import { type StudyRole, studyRoleMay } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Problem } from "@/ui/problem";
import { Card, EmptyState, Spinner } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";
import { seconds } from "@/ui/format";
import { AgreementPanel } from "../coding/agreement-panel";
import { ResultsByCondition } from "./results-by-condition";

export function ResultsTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const figures = useQuery(trpc.studies.figures.queryOptions({ studyId }));
  if (figures.isPending) return <Spinner label="Computing the study's figures…" />;
  if (figures.error) return <Problem error={figures.error} />;
  const s = figures.data;
  if (!s.trials.length)
    return <EmptyState title="No finished trials yet.">Figures appear here as trials are completed.</EmptyState>;
  const c = s.consistency;
  return (
    <div className="space-y-6">
      <div className="grid gap-4 sm:grid-cols-4">
        <Figure label="Finished trials" value={`${c.completed} completed / ${c.trials}`} />
        <Figure
          label="Execution fidelity"
          value={
            c.meanFidelity === null
              ? "—"
              : `${c.meanFidelity.toFixed(1)} %${c.sdFidelity === null ? "" : ` ± ${c.sdFidelity.toFixed(1)}`}`
          }
        />
        <Figure label="Run exactly as scripted" value={`${c.withoutDeviation} of ${c.trials}`} />
        <Figure
          label="Deviations"
          value={
            Object.entries(c.deviationsByKind)
              .map(([k, n]) => `${n} ${k.replace("_", " ")}`)
              .join(", ") || "none"
          }
        />
      </div>
      <section aria-label="Step timing across participants">
        <h2 className="mb-2 text-lg font-semibold">Time in each step</h2>
        <StepTimingPlot steps={s.steps} />
      </section>
      <ResultsByCondition studyId={studyId} />
      <AgreementPanel studyId={studyId} canKeep={studyRoleMay(role, "experiment.edit")} />
      <section aria-label="Trials">
        <h2 className="mb-2 text-lg font-semibold">Trials</h2>
        <Table>
          <thead>
            <tr>
              <Th>Participant</Th>
              <Th>Condition</Th>
              <Th>Fidelity</Th>
              <Th>Executed / planned</Th>
              <Th>Deviations</Th>
              <Th>Jumps by hand</Th>
              <Th>Unscripted</Th>
              <Th>Duration</Th>
            </tr>
          </thead>
          <tbody>
            {s.trials.map((t) => (
              <tr key={t.trialId}>
                <Td className="font-mono">
                  <Link className="text-brand-700 hover:underline" href={`/trials/${t.trialId}/analysis`}>
                    {t.participantCode}
                  </Link>
                </Td>
                <Td>{t.condition ?? "—"}</Td>
                <Td>{t.executionFidelity} %</Td>
                <Td>
                  {t.executed} / {t.planned}
                </Td>
                <Td>{t.deviations}</Td>
                <Td>{t.branchesByHand}</Td>
                <Td>{t.unscripted}</Td>
                <Td>{seconds(t.durationMs)}</Td>
              </tr>
            ))}
          </tbody>
        </Table>
      </section>
    </div>
  );
}

function Figure({ label, value }: { label: string; value: string }) {
  return (
    <Card className="p-4">
      <div className="text-xs text-slate-500">{label}</div>
      <div className="mt-1 text-lg font-semibold">{value}</div>
    </Card>
  );
}

/** One row per step: a bar from the shortest to the longest time, a mark at the median. */
function StepTimingPlot({ steps }: { steps: StudySummary["steps"] }) {
  const longest = Math.max(1, ...steps.map((s) => s.durationMs?.max ?? 0));
  const x = (ms: number) => `${(ms / longest) * 100}%`;
  return (
    <Card
      className="space-y-2 p-4"
      role="img"
      aria-label="Median time in each step, with the range across participants"
    >
      {steps.map((s) => (
        <div key={s.name} className="grid grid-cols-[12rem_1fr_9rem] items-center gap-3 text-sm">
          <span className="truncate">{s.name}</span>
          <div className="relative h-4 rounded bg-slate-100">
            {s.durationMs && (
              <>
                <div
                  className="absolute top-1 h-2 rounded bg-brand-200"
                  style={{ left: x(s.durationMs.min), width: `calc(${x(s.durationMs.max - s.durationMs.min)} + 2px)` }}
                />
                <div className="absolute top-0 h-4 w-1 rounded bg-brand-700" style={{ left: x(s.durationMs.median) }} />
              </>
            )}
          </div>
          <span className="text-xs text-slate-500">
            {s.durationMs ? `${seconds(s.durationMs.median)} (n=${s.durationMs.n})` : `not reached`}
          </span>
        </div>
      ))}
    </Card>
  );
}
