"use client";
// The trial's events and annotations in time order, each a button that
// seeks there. A trial of 100k events would be 100k buttons: only the rows in
// view (and a margin) are drawn, and the arrow keys, Home and End move along
// the whole list, bringing the row they reach into view.
import { useEffect, useState } from "react";
import { Badge, Card } from "@/ui/surface";
import { seconds } from "@/ui/format";
import { useRowsInView } from "@/ui/virtual";

export type TimelineItem =
  | { at: number; kind: "event"; e: { type: string; deviation?: string | null } }
  | { at: number; kind: "annotation"; m: { label: string; note: string | null; authorName: string | null } };

const ROW = 32;
const VIEW = 480;

const MOVES: Record<string, (i: number, count: number) => number> = {
  ArrowDown: (i, count) => Math.min(count - 1, i + 1),
  ArrowUp: (i) => Math.max(0, i - 1),
  PageDown: (i, count) => Math.min(count - 1, i + VIEW / ROW),
  PageUp: (i) => Math.max(0, i - VIEW / ROW),
  Home: () => 0,
  End: (_, count) => count - 1,
};

export function EventList({
  items,
  current,
  about,
  onSeek,
}: {
  items: TimelineItem[];
  /** The row the playhead is in, or -1. */
  current: number;
  about: (e: object) => string | null | undefined;
  onSeek: (ms: number) => void;
}) {
  const rows = useRowsInView(items.length, ROW, VIEW);
  // The row the keyboard moved to: focused once it is drawn.
  const [focusing, setFocusing] = useState<number | null>(null);
  useEffect(() => {
    if (focusing === null) return;
    document.querySelector<HTMLButtonElement>(`[data-event-row="${focusing}"]`)?.focus();
  }, [focusing]);
  const onKeyDown = (event: React.KeyboardEvent) => {
    const move = MOVES[event.key];
    const at = Number((event.target as HTMLElement).dataset.eventRow);
    if (!move || Number.isNaN(at)) return;
    event.preventDefault();
    const next = move(at, items.length);
    rows.reveal(next);
    setFocusing(next);
  };
  return (
    <Card className="text-sm">
      {/* biome-ignore lint/a11y/useSemanticElements: a group so that its name is read with the rows it holds; a fieldset is for form fields */}
      <div
        ref={rows.ref}
        className="overflow-y-auto"
        style={{ maxHeight: VIEW }}
        onKeyDown={onKeyDown}
        aria-label={`Events and annotations (${items.length}); arrow keys move between them`}
        role="group"
      >
        <div style={{ height: rows.before }} />
        {items.slice(rows.from, rows.to).map((item, k) => {
          const i = rows.from + k;
          return (
            <button
              key={i}
              type="button"
              data-event-row={i}
              aria-current={current === i ? "time" : undefined}
              onClick={() => onSeek(item.at)}
              style={{ height: ROW }}
              className={`flex w-full items-center gap-3 overflow-hidden whitespace-nowrap border-b border-slate-100 px-4 text-left enabled:hover:bg-slate-50 ${current === i ? "bg-brand-50" : ""}`}
            >
              <span className="w-16 shrink-0 font-mono text-xs text-slate-600">{seconds(item.at)}</span>
              {item.kind === "annotation" ? (
                <span className="truncate">
                  <Badge tone="violet">marked</Badge> <strong>{item.m.label}</strong> {item.m.note}{" "}
                  <span className="text-xs text-slate-600">by {item.m.authorName}</span>
                </span>
              ) : (
                <span className="truncate">
                  {item.e.type}
                  {about(item.e) && <span className="text-slate-500"> · {about(item.e)}</span>}
                  {item.e.deviation && <Badge tone="amber">{item.e.deviation.replace("_", " ")}</Badge>}
                </span>
              )}
            </button>
          );
        })}
        <div style={{ height: rows.after }} />
      </div>
    </Card>
  );
}
