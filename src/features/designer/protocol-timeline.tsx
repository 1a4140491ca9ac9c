"use client";
// The protocol as a vertical timeline: steps in order, each with its ordered
// actions; actions that run together share a frame. Steps and actions are
// sortable; each step ends in a drop zone for new blocks.
import { useDroppable } from "@dnd-kit/core";
import { SortableContext, useSortable, verticalListSortingStrategy } from "@dnd-kit/sortable";
import { CSS } from "@dnd-kit/utilities";
import { AlertCircle, AlertTriangle, CornerDownRight, GripVertical, Link2 } from "lucide-react";
import { memo, useMemo, useRef } from "react";
import type { DesignAction, DesignStep } from "@/core/designer/types";
import { describeExit } from "@/core/protocol/flow";
import { type FlowEdge, flowEdges } from "@/core/trial";
import { cn } from "@/ui/cn";

export type Selection = { kind: "step" | "action"; id: string } | null;

/** What the timeline shows about one block's problems. */
export interface Marks {
  errors: string[];
  warnings: string[];
}

export const stepDragId = (id: string) => `step:${id}`;
export const actionDragId = (id: string) => `act:${id}`;
export const dropZoneId = (stepId: string) => `drop:${stepId}`;

export function ProtocolTimeline({
  steps,
  selection,
  marks,
  blockName,
  onSelect,
}: {
  steps: DesignStep[];
  selection: Selection;
  marks: Map<string, Marks>;
  blockName: (type: string) => string;
  onSelect: (s: Selection) => void;
}) {
  const items = useSameList(steps.map((s) => stepDragId(s.id)));
  const edges = useMemo(() => flowEdges({ steps }), [steps]);
  return (
    <SortableContext items={items} strategy={verticalListSortingStrategy}>
      <ol aria-label="Protocol" className="space-y-3">
        {steps.map((step, index) => {
          const selected =
            selection && (selection.id === step.id || step.actions.some((a) => a.id === selection.id))
              ? selection.id
              : null;
          return (
            <StepCard
              key={step.id}
              step={step}
              index={index}
              selected={selected}
              leadsTo={leadsTo(steps, index, edges)}
              marksKey={marksKey(step, marks)}
              marks={marks}
              blockName={blockName}
              onSelect={onSelect}
            />
          );
        })}
      </ol>
    </SortableContext>
  );
}

/** Where a step leads, in words; a step whose question routes every answer leads where the answer says. */
function leadsTo(steps: DesignStep[], index: number, edges: FlowEdge[]): string {
  const own = edges.filter((e) => e.from === index && e.kind !== "timeout");
  if (own.length > 0 && own.every((e) => e.kind === "answer")) return "where the answer leads";
  return describeExit(steps, index);
}

/**
 * The previous array while the ids are the same: a new array makes dnd-kit
 * re-render every sortable in the list, and an edit rarely changes the order.
 */
function useSameList(ids: string[]): string[] {
  const last = useRef(ids);
  if (last.current.length !== ids.length || last.current.some((id, i) => id !== ids[i])) last.current = ids;
  return last.current;
}

/** A step re-renders only when it, its selection or its problems change: 1,000 actions stay quick. */
function marksKey(step: DesignStep, marks: Map<string, Marks>) {
  return [step.id, ...step.actions.map((a) => a.id)].map((id) => JSON.stringify(marks.get(id) ?? "")).join("|");
}

interface StepProps {
  step: DesignStep;
  /** Where the step leads after its actions, in words. */
  leadsTo: string;
  index: number;
  selected: string | null;
  marksKey: string;
  marks: Map<string, Marks>;
  blockName: (type: string) => string;
  onSelect: (s: Selection) => void;
}

const StepCard = memo(
  function StepCard({ step, index, leadsTo, selected, marks, blockName, onSelect }: StepProps) {
    const sortable = useSortable({ id: stepDragId(step.id), data: { stepId: step.id } });
    const drop = useDroppable({ id: dropZoneId(step.id), data: { stepId: step.id } });
    const stepMarks = marks.get(step.id);
    const items = useSameList(step.actions.map((a) => actionDragId(a.id)));
    return (
      <li
        ref={sortable.setNodeRef}
        style={{ transform: CSS.Translate.toString(sortable.transform), transition: sortable.transition }}
        data-step={step.name}
        className={cn(
          "rounded-lg border bg-white shadow-sm",
          selected === step.id ? "border-brand-500 ring-2 ring-brand-500/30" : "border-slate-200",
          sortable.isDragging && "opacity-60",
        )}
      >
        <div className="flex items-center gap-2 border-b border-slate-100 px-3 py-2">
          <button
            type="button"
            aria-label={`Drag step ${step.name}`}
            className="cursor-grab text-slate-400 hover:text-slate-700"
            {...sortable.attributes}
            {...sortable.listeners}
          >
            <GripVertical className="h-4 w-4" aria-hidden />
          </button>
          <button
            type="button"
            className="flex-1 text-left"
            onClick={() => onSelect({ kind: "step", id: step.id })}
            aria-label={`Step ${index + 1}: ${step.name}${step.description ? ` ${step.description}` : ""}`}
          >
            <span className="text-xs font-semibold text-slate-500">Step {index + 1}</span>{" "}
            <span className="font-semibold">{step.name}</span>
            {/* A space, not only a margin: the visible words must read as the button's name does (WCAG 2.5.3). */}
            {step.description && <span className="ml-1 text-xs text-slate-500"> {step.description}</span>}
          </button>
          <MarkIcons marks={stepMarks} />
        </div>
        <SortableContext items={items} strategy={verticalListSortingStrategy}>
          <ul className="space-y-1 p-2">
            {step.actions.map((action, i) => {
              const prev = step.actions[i - 1];
              const next = step.actions[i + 1];
              const group = action.parallelGroup;
              const joinsAbove = Boolean(group && prev?.parallelGroup === group);
              const joinsBelow = Boolean(group && next?.parallelGroup === group);
              return (
                <ActionCard
                  key={action.id}
                  action={action}
                  label={blockName(action.type)}
                  selected={selected === action.id}
                  marks={marks.get(action.id)}
                  joinsAbove={joinsAbove}
                  joinsBelow={joinsBelow}
                  onSelect={onSelect}
                />
              );
            })}
          </ul>
        </SortableContext>
        <div
          ref={drop.setNodeRef}
          data-drop-zone={step.name}
          className={cn(
            "mx-2 mb-2 rounded-md border border-dashed px-3 py-2 text-center text-xs",
            drop.isOver ? "border-brand-500 bg-brand-50 text-brand-700" : "border-slate-300 text-slate-500",
          )}
        >
          {step.actions.length ? "Drop a block here to add it at the end" : "Empty step: drop a block here"}
        </div>
        <p
          data-leads-to={leadsTo}
          className={cn(
            "flex items-center gap-1 border-t border-slate-100 px-3 py-1.5 text-xs",
            // A chosen way on stands out; the plain "next step" stays quiet.
            step.after && step.after.to !== "next" ? "font-medium text-brand-800" : "text-slate-600",
          )}
        >
          <CornerDownRight className="h-3.5 w-3.5" aria-hidden /> Then {leadsTo}
        </p>
      </li>
    );
  },
  (a, b) =>
    a.step === b.step &&
    a.index === b.index &&
    a.leadsTo === b.leadsTo &&
    a.selected === b.selected &&
    a.marksKey === b.marksKey &&
    a.blockName === b.blockName &&
    a.onSelect === b.onSelect,
);

const ActionCard = memo(function ActionCard({
  action,
  label,
  selected,
  marks,
  joinsAbove,
  joinsBelow,
  onSelect,
}: {
  action: DesignAction;
  label: string;
  selected: boolean;
  marks: Marks | undefined;
  joinsAbove: boolean;
  joinsBelow: boolean;
  onSelect: (s: Selection) => void;
}) {
  const sortable = useSortable({ id: actionDragId(action.id), data: { actionId: action.id } });
  const summary = summarise(action);
  return (
    <li
      ref={sortable.setNodeRef}
      style={{ transform: CSS.Translate.toString(sortable.transform), transition: sortable.transition }}
      className={cn(
        "relative",
        (joinsAbove || joinsBelow) && "border-l-4 border-violet-300 pl-2",
        joinsAbove && "-mt-1 pt-1",
        sortable.isDragging && "opacity-60",
      )}
    >
      {!joinsAbove && joinsBelow && (
        <div className="mb-0.5 flex items-center gap-1 text-[11px] font-medium text-violet-700">
          <Link2 className="h-3 w-3" aria-hidden /> Run together
        </div>
      )}
      {/* biome-ignore lint/a11y/useSemanticElements: a sortable block (dnd-kit's attributes and listeners) that holds other controls; a <button> may not */}
      <div
        {...sortable.attributes}
        {...sortable.listeners}
        role="button"
        tabIndex={0}
        data-action={action.name || label}
        aria-pressed={selected}
        onClick={() => onSelect({ kind: "action", id: action.id })}
        onKeyDown={(e) => {
          if (e.key === "Enter" || e.key === " ") {
            e.preventDefault();
            onSelect({ kind: "action", id: action.id });
          }
        }}
        className={cn(
          "flex cursor-pointer items-start gap-2 rounded-md border px-2.5 py-1.5 text-sm focus:outline-none focus:ring-2 focus:ring-brand-500/40",
          selected ? "border-brand-500 bg-brand-50" : "border-slate-200 bg-slate-50 hover:border-slate-400",
          marks?.errors.length ? "border-red-400" : "",
        )}
      >
        <GripVertical className="mt-0.5 h-4 w-4 shrink-0 text-slate-300" aria-hidden />
        <div className="min-w-0 flex-1">
          <div>
            <span className="font-medium">{action.name || label}</span>
            {/* slate-600: slate-500 is 4.4:1 on a selected block's brand-50 */}
            {action.name && <span className="ml-1.5 text-xs text-slate-600">{label}</span>}
          </div>
          {summary && <div className="truncate text-xs text-slate-600">{summary}</div>}
        </div>
        <MarkIcons marks={marks} />
      </div>
    </li>
  );
});

function MarkIcons({ marks }: { marks: Marks | undefined }) {
  if (!marks) return null;
  return (
    <span className="flex shrink-0 gap-1">
      {marks.errors.length > 0 && (
        <span title={marks.errors.join("\n")} className="text-red-600">
          <AlertCircle
            className="h-4 w-4"
            aria-label={`${marks.errors.length} problem(s): ${marks.errors.join(" ")}`}
          />
        </span>
      )}
      {marks.warnings.length > 0 && (
        <span title={marks.warnings.join("\n")} className="text-amber-600">
          <AlertTriangle className="h-4 w-4" aria-label={`Warning: ${marks.warnings.join(" ")}`} />
        </span>
      )}
    </span>
  );
}

/** One line a researcher can read at a glance: the speech, the seconds, the answers. */
function summarise(action: DesignAction): string {
  const p = action.parameters;
  if (typeof p.text === "string") return `“${p.text}”`;
  if (typeof p.seconds === "number") return `${p.seconds} s`;
  if (Array.isArray(p.options)) return (p.options as Array<{ label?: string }>).map((o) => o.label).join(" / ");
  const shown = Object.entries(p).filter(([, v]) => typeof v === "string" || typeof v === "number");
  return shown.map(([k, v]) => `${k}: ${String(v)}`).join(", ");
}
