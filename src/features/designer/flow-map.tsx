"use client";
// The experiment as a map: steps top to bottom in list order, each way on as
// an arrow. "Next" into the step below is a short arrow; a jump or a rejoin
// curves round on the right, an answer's branch or a sensed event's way on
// the left, each in its own lane so arrows never overlap. A loop's way back is
// its own colour, with its bound written at its head.
import { useMemo } from "react";
import type { DesignDraft } from "@/core/designer/types";
import { type FlowEdge, flowEdges } from "@/core/trial";

const BOX = { x: 150, width: 240, height: 36, gap: 28 };
const LANE = 14;

export function FlowMap({ draft, onSelect }: { draft: DesignDraft; onSelect: (stepId: string) => void }) {
  const edges = useMemo(() => flowEdges(draft), [draft]);
  if (draft.steps.length === 0) return <p className="text-sm text-slate-600">Add a step to see the flow.</p>;
  const top = (i: number) => 8 + i * (BOX.height + BOX.gap);
  const endIndex = draft.steps.length;
  const target = (e: FlowEdge) => (e.to === "end" ? endIndex : e.to);
  // An edge with a label (a loop's way on after its last time) goes round, where its label has room.
  const around = edges.filter((e) => !(e.kind === "after" && !e.label && target(e) === e.from + 1));
  const lanes = { left: 0, right: 0 };
  const laneOf = new Map(
    around.map((e) => [e, e.kind === "answer" || e.kind === "sensed" ? ++lanes.left : ++lanes.right]),
  );
  const height = top(endIndex) + BOX.height + 8;
  const width = BOX.x * 2 + BOX.width;
  const name = (i: number) => draft.steps[i]?.name || `Step ${i + 1}`;
  return (
    <figure className="space-y-2">
      {/* biome-ignore lint/a11y/useSemanticElements: an SVG cannot be a fieldset; its steps are buttons, so it is a group, not an image */}
      <svg
        role="group"
        aria-labelledby="flow-map-title"
        viewBox={`0 0 ${width} ${height}`}
        className="w-full max-w-2xl"
        style={{ maxHeight: "70vh" }}
      >
        <title id="flow-map-title">Flow map of the experiment</title>
        <defs>
          <marker id="flow-arrow" viewBox="0 0 8 8" refX="7" refY="4" markerWidth="7" markerHeight="7" orient="auto">
            <path d="M0,0 L8,4 L0,8 z" className="fill-slate-500" />
          </marker>
        </defs>
        {edges.map((e, i) => {
          const to = target(e);
          const y1 = top(e.from) + BOX.height / 2;
          const y2 = top(to) + BOX.height / 2;
          const lane = laneOf.get(e);
          if (lane === undefined) {
            const x = BOX.x + BOX.width / 2;
            return (
              <line
                key={i}
                x1={x}
                y1={top(e.from) + BOX.height}
                x2={x}
                y2={top(to) - 2}
                className="stroke-slate-500"
                markerEnd="url(#flow-arrow)"
              />
            );
          }
          const left = e.kind === "answer" || e.kind === "sensed";
          const edge = left ? BOX.x : BOX.x + BOX.width;
          const out = left ? edge - lane * LANE : edge + lane * LANE;
          return (
            <g key={i}>
              <path
                d={`M${edge},${y1 - 6} H${out} V${y2 + 6} H${edge + (left ? -2 : 2)}`}
                fill="none"
                className={left ? "stroke-brand-600" : e.kind === "loop" ? "stroke-violet-700" : "stroke-amber-700"}
                // A time limit's way on is dashed: taken only if the time runs out; a sensed event's, dotted.
                strokeDasharray={e.kind === "timeout" ? "4 3" : e.kind === "sensed" ? "1 3" : undefined}
                markerEnd="url(#flow-arrow)"
              />
              {e.label && (
                // At the arrow's head, where each answer has a row of its own; the halo keeps it legible over lanes.
                <text
                  x={left ? edge - 6 : edge + 6}
                  y={y2 + 2}
                  textAnchor={left ? "end" : "start"}
                  paintOrder="stroke"
                  strokeWidth={3}
                  className="fill-brand-800 stroke-white text-[10px]"
                >
                  {e.label}
                </text>
              )}
            </g>
          );
        })}
        {draft.steps.map((step, i) => (
          // biome-ignore lint/a11y/useSemanticElements: an SVG group cannot be a button; it acts as one
          <g
            key={step.id}
            role="button"
            tabIndex={0}
            aria-label={`Step ${i + 1}: ${name(i)}`}
            className="cursor-pointer focus:outline-none [&:focus>rect]:stroke-brand-600"
            onClick={() => onSelect(step.id)}
            onKeyDown={(e) => (e.key === "Enter" || e.key === " ") && onSelect(step.id)}
          >
            <rect
              x={BOX.x}
              y={top(i)}
              width={BOX.width}
              height={BOX.height}
              rx={6}
              className="fill-white stroke-slate-300"
              strokeWidth={1.5}
            />
            <text x={BOX.x + 10} y={top(i) + 23} className="fill-slate-900 text-[12px]">
              {i + 1}. {name(i).length > 32 ? `${name(i).slice(0, 31)}…` : name(i)}
            </text>
          </g>
        ))}
        <rect
          x={BOX.x + BOX.width / 4}
          y={top(endIndex)}
          width={BOX.width / 2}
          height={BOX.height}
          rx={18}
          className="fill-slate-100 stroke-slate-400"
        />
        <text
          x={BOX.x + BOX.width / 2}
          y={top(endIndex) + 23}
          textAnchor="middle"
          className="fill-slate-700 text-[12px]"
        >
          End of trial
        </text>
      </svg>
      <figcaption className="text-xs text-slate-600">
        Arrows on the left are answers of a question; on the right, a step that goes somewhere other than the next step
        (dashed: when a time limit runs out; violet: a loop going back, at most the times it says). Select a step to
        edit it.
      </figcaption>
      <ul className="sr-only">
        {edges.map((e, i) => (
          <li key={i}>
            {name(e.from)} {edgeWords(e)} leads to {e.to === "end" ? "the end of the trial" : name(e.to)}
          </li>
        ))}
      </ul>
    </figure>
  );
}

/** What an edge is, for a screen reader: "(answer “Yes”)", "(back, at most 2 times)", "(when its time limit runs out: 10 s)". */
function edgeWords(e: FlowEdge): string {
  if (!e.label) return "";
  if (e.kind === "answer") return `(answer "${e.label}")`;
  return e.kind === "timeout" ? `(when its time limit runs out: ${e.label})` : `(${e.label})`;
}
