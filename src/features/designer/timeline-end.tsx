"use client";
// Below the last step: a drop there (or at the window's bottom edge, under
// the timeline) adds the block at the end of the last step, or to a new step
// when there is none. Before, a drop that landed on no step did nothing.
import { type CollisionDetection, pointerWithin, rectIntersection, useDndContext, useDroppable } from "@dnd-kit/core";
import type { ReactNode } from "react";
import { cn } from "@/ui/cn";

export const TIMELINE_END = "end:timeline";

/** How near the window's bottom edge a drop under the timeline still counts as "at the end". */
const BOTTOM_EDGE_PX = 48;

/**
 * The pointer decides where a block lands; the area below the last step only
 * when no step or action is under it; then the closest overlap; then, under
 * the timeline's column near the window's bottom, the end.
 */
export const collision: CollisionDetection = (args) => {
  const within = pointerWithin(args);
  const specific = within.filter((c) => c.id !== TIMELINE_END);
  if (specific.length) return specific;
  if (within.length) return within;
  const overlapping = rectIntersection(args).filter((c) => c.id !== TIMELINE_END);
  if (overlapping.length) return overlapping;
  const end = args.droppableRects.get(TIMELINE_END);
  const pointer = args.pointerCoordinates;
  if (!end || !pointer || pointer.x < end.left || pointer.x > end.right) return [];
  const atBottom = pointer.y >= end.top || pointer.y >= window.innerHeight - BOTTOM_EDGE_PX;
  return atBottom ? [{ id: TIMELINE_END }] : [];
};

/** Fills the timeline's column below the last step; says where a drop goes while something is dragged. */
export function TimelineEnd({ lastStep, children }: { lastStep: string | null; children: ReactNode }) {
  const { active } = useDndContext();
  const drop = useDroppable({ id: TIMELINE_END });
  const dragging = Boolean(active);
  return (
    <div ref={drop.setNodeRef} data-drop-zone="(end of the timeline)" className="flex min-h-32 flex-1 flex-col gap-2">
      {children}
      {dragging && (
        <div
          className={cn(
            "flex-1 rounded-md border border-dashed px-3 py-4 text-center text-xs",
            drop.isOver ? "border-brand-500 bg-brand-50 text-brand-700" : "border-slate-300 text-slate-600",
          )}
        >
          {lastStep === null ? "Drop here to add it to a new step" : `Drop here to add it at the end of “${lastStep}”`}
        </div>
      )}
    </div>
  );
}
