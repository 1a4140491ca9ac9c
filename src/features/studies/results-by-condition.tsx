"use client";
// The conditions side by side: for each measure, a plot (a bar to the mean,
// a line over the range) and the table a paper reports (n, mean, SD, median,
// range), with the same figures as a tidy CSV for R or a spreadsheet; then
// the answers recorded, counted per condition.
import { useQuery } from "@tanstack/react-query";
import type { Measure } from "@/core/analysis/by-condition";
import { useTRPC } from "@/lib/trpc";
import { DownloadLink } from "@/ui/download-link";
import { seconds } from "@/ui/format";
import { Problem } from "@/ui/problem";
import { Card, Spinner } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";
import { AnswerCounts } from "./answer-counts";

const NO_CONDITION = "No condition";

/** A value in the measure's own unit: durations in seconds, the rest to two decimals at most. */
function show(unit: Measure["unit"], value: number | null | undefined) {
  if (value === null || value === undefined) return "—";
  if (unit === "ms") return seconds(value);
  const text = Number(value.toFixed(2)).toString();
  return unit === "%" ? `${text} %` : text;
}

export function ResultsByCondition({ studyId }: { studyId: string }) {
  const trpc = useTRPC();
  const results = useQuery(trpc.studies.resultsByCondition.queryOptions({ studyId }));
  if (results.isPending) return <Spinner label="Comparing the conditions…" />;
  if (results.error) return <Problem error={results.error} />;
  const { conditions, measures, answers } = results.data;
  return (
    <section aria-labelledby="by-condition" className="space-y-4">
      <div className="flex flex-wrap items-baseline justify-between gap-2">
        <h2 id="by-condition" className="text-lg font-semibold">
          By condition
        </h2>
        <DownloadLink href={`/api/studies/${studyId}/results-by-condition`}>
          Download as CSV (one row per condition and measure)
        </DownloadLink>
      </div>
      <p className="text-sm text-slate-600">
        {conditions.map((c) => `${c.condition ?? NO_CONDITION}: ${c.trials} trials`).join(" · ")}
      </p>
      {measures.map((m) => (
        <MeasureCard key={m.measure} measure={m} />
      ))}
      <AnswerCounts answers={answers} noCondition={NO_CONDITION} />
    </section>
  );
}

function MeasureCard({ measure }: { measure: Measure }) {
  return (
    <Card className="space-y-3 p-4">
      <h3 className="font-medium">{measure.measure}</h3>
      <ConditionPlot measure={measure} />
      <Table>
        <thead>
          <tr>
            <Th>Condition</Th>
            <Th>n</Th>
            <Th>Mean</Th>
            <Th>SD</Th>
            <Th>Median</Th>
            <Th>Range</Th>
          </tr>
        </thead>
        <tbody>
          {measure.byCondition.map(({ condition, stats }) => (
            <tr key={condition ?? NO_CONDITION}>
              <Td>{condition ?? NO_CONDITION}</Td>
              <Td>{stats?.n ?? 0}</Td>
              <Td>{show(measure.unit, stats?.mean)}</Td>
              <Td>{show(measure.unit, stats?.sd)}</Td>
              <Td>{show(measure.unit, stats?.median)}</Td>
              <Td>{stats ? `${show(measure.unit, stats.min)} – ${show(measure.unit, stats.max)}` : "—"}</Td>
            </tr>
          ))}
        </tbody>
      </Table>
    </Card>
  );
}

const ROW = 28;
const LABEL = 170;
const PLOT = 360;

/** One row per condition: a bar from zero to the mean, a line with end marks from the minimum to the maximum. */
function ConditionPlot({ measure }: { measure: Measure }) {
  const { unit, byCondition } = measure;
  // Fidelity is read against its 100 %; the rest against the largest value seen.
  const top = Math.max(unit === "%" ? 100 : 0, ...byCondition.map((c) => c.stats?.max ?? 0)) || 1;
  const x = (v: number) => LABEL + (Math.max(0, v) / top) * PLOT;
  const height = byCondition.length * ROW + 4;
  return (
    <svg
      role="img"
      aria-label={`${measure.measure}: mean per condition, with the range from minimum to maximum`}
      viewBox={`0 0 ${LABEL + PLOT + 110} ${height}`}
      className="w-full max-w-3xl"
    >
      {byCondition.map(({ condition, stats }, i) => {
        const mid = i * ROW + ROW / 2 + 2;
        return (
          <g key={condition ?? NO_CONDITION}>
            <text x={LABEL - 8} y={mid + 4} textAnchor="end" className="fill-slate-700 text-[12px]">
              {(condition ?? NO_CONDITION).slice(0, 24)}
            </text>
            <line x1={LABEL} x2={LABEL} y1={mid - 10} y2={mid + 10} className="stroke-slate-300" />
            {stats ? (
              <>
                <rect
                  x={LABEL}
                  y={mid - 7}
                  width={x(stats.mean) - LABEL}
                  height={14}
                  rx={2}
                  className="fill-brand-100 stroke-brand-500"
                />
                <line
                  x1={x(stats.min)}
                  x2={x(stats.max)}
                  y1={mid}
                  y2={mid}
                  strokeWidth={2}
                  className="stroke-brand-700"
                />
                <line
                  x1={x(stats.min)}
                  x2={x(stats.min)}
                  y1={mid - 5}
                  y2={mid + 5}
                  strokeWidth={2}
                  className="stroke-brand-700"
                />
                <line
                  x1={x(stats.max)}
                  x2={x(stats.max)}
                  y1={mid - 5}
                  y2={mid + 5}
                  strokeWidth={2}
                  className="stroke-brand-700"
                />
                <text x={LABEL + PLOT + 8} y={mid + 4} className="fill-slate-500 text-[11px]">
                  {show(unit, stats.mean)} (n={stats.n})
                </text>
              </>
            ) : (
              <text x={LABEL + 8} y={mid + 4} className="fill-slate-500 text-[11px]">
                no values
              </text>
            )}
          </g>
        );
      })}
    </svg>
  );
}
