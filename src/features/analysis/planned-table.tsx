"use client";
// Planned versus executed: one row per designed action. A long protocol is
// thousands of rows: only the rows in view (and a margin) are drawn, in a box
// that scrolls and takes focus, so the arrow, Page, Home and End keys scroll
// it through every row. The table keeps its full height (space above and
// below it, not rows of it) and says how many rows it has (aria-rowcount, each
// drawn row its aria-rowindex), so a screen reader tells where in the whole
// table a row is.
import { type FidelityReport, outcomeWords } from "@/core/analysis/fidelity";
import { seconds } from "@/ui/format";
import { Badge, type Tone } from "@/ui/surface";
import { Td, Th } from "@/ui/table";
import { useRowsInView } from "@/ui/virtual";

const OUTCOME_TONE: Record<string, Tone> = {
  executed: "green",
  skipped: "amber",
  failed: "red",
  not_sent: "slate",
  unknown: "amber",
  timed_out: "red",
  not_reached: "slate",
  running: "blue",
};

const ROW = 40;
const VIEW = 560;

export function PlannedTable({ report }: { report: FidelityReport }) {
  const { actions } = report;
  const rows = useRowsInView(actions.length, ROW, VIEW);
  const stepNames = new Map(report.steps.map((s) => [s.stepId, s.name]));
  return (
    <section
      ref={rows.ref}
      aria-label={`Planned actions (${actions.length}); the arrow keys scroll them`}
      // biome-ignore lint/a11y/noNoninteractiveTabindex: a scrollable region must take focus so the keyboard can scroll it (WCAG 2.1.1, axe's scrollable-region-focusable)
      tabIndex={0}
      className="overflow-auto rounded-lg border border-slate-200 bg-white focus:outline-none focus-visible:ring-2 focus-visible:ring-brand-600"
      style={{ maxHeight: VIEW }}
    >
      <div style={{ paddingTop: rows.before, paddingBottom: rows.after }}>
        <table className="w-full text-left text-sm" aria-rowcount={actions.length + 1}>
          <thead className="sticky top-0 z-10">
            <tr aria-rowindex={1}>
              <Th>Step</Th>
              <Th>Action</Th>
              <Th>Outcome</Th>
              <Th>At</Th>
              <Th>Took</Th>
              <Th>To robot</Th>
            </tr>
          </thead>
          <tbody>
            {actions.slice(rows.from, rows.to).map((a, k) => (
              <tr
                key={a.actionId}
                aria-rowindex={rows.from + k + 2}
                data-planned-row={rows.from + k}
                style={{ height: ROW }}
                className="whitespace-nowrap"
              >
                <Td className="py-0">{stepNames.get(a.stepId)}</Td>
                <Td className="py-0">{a.name}</Td>
                <Td className="py-0">
                  <Badge tone={OUTCOME_TONE[a.outcome]}>{outcomeWords(a.outcome)}</Badge>{" "}
                  {a.outOfOrder && <Badge tone="amber">out of order</Badge>}
                  {a.answer !== null && <span data-answer>answered “{a.answer}”</span>}
                </Td>
                <Td className="py-0">{seconds(a.requestedMs)}</Td>
                <Td className="py-0">
                  {seconds(a.durationMs)}
                  {/* The robot did not say when it was done: the time is an estimate or a delivery, not its own. */}
                  {a.confirmation === "unconfirmed" && (
                    <>
                      {" "}
                      <Badge tone="amber">unconfirmed</Badge>
                    </>
                  )}
                </Td>
                <Td className="py-0">{a.dispatchLatencyMs === null ? "—" : `${a.dispatchLatencyMs.toFixed(0)} ms`}</Td>
              </tr>
            ))}
          </tbody>
        </table>
      </div>
    </section>
  );
}
