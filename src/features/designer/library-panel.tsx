"use client";
// The block library: searchable, grouped, each block dragged into a step or
// added to the selected step with Enter (the keyboard way). A block the robot
// carries out with its own actions lists them under it, as its variants.
import { useDraggable } from "@dnd-kit/core";
import { ChevronDown, ChevronRight, Search } from "lucide-react";
import { memo, useMemo, useState } from "react";
import type { Block, BlockCategory } from "@/core/designer/blocks";
import { searchLibrary, type LibraryEntry } from "@/core/designer/library";
import { Input } from "@/ui/field";

const CATEGORY_NAMES: Record<BlockCategory, string> = {
  speech: "Speech",
  movement: "Gestures and movement",
  timing: "Timing",
  wizard: "For the wizard",
  logic: "Answers, branches and ending",
  robot: "This robot's own actions",
};

export const libraryDragId = (type: string) => `lib:${type}`;

export const LibraryPanel = memo(function LibraryPanel({
  entries,
  robotName,
  unsupported,
  onAdd,
}: {
  entries: LibraryEntry[];
  robotName: string;
  unsupported: Set<string>;
  onAdd: (block: Block) => void;
}) {
  const [query, setQuery] = useState("");
  const groups = useMemo(() => {
    const shown = searchLibrary(entries, query);
    return (Object.keys(CATEGORY_NAMES) as BlockCategory[])
      .map((c) => ({ category: c, entries: shown.filter((e) => e.block.category === c) }))
      .filter((g) => g.entries.length);
  }, [entries, query]);
  return (
    <section aria-label="Block library" className="flex min-h-0 flex-col gap-3">
      <div className="relative">
        <Search className="pointer-events-none absolute left-2.5 top-3 h-4 w-4 text-slate-400" aria-hidden />
        <Input
          aria-label="Search blocks"
          placeholder="Search blocks…"
          className="pl-8"
          value={query}
          onChange={(e) => setQuery(e.target.value)}
        />
      </div>
      <p className="text-xs text-slate-500">Drag a block into a step, or select a step and press Enter on a block.</p>
      <div className="min-h-0 flex-1 space-y-4 overflow-y-auto pr-1">
        {groups.map((g) => (
          <section key={g.category}>
            <h3 className="mb-1 text-xs font-semibold uppercase tracking-wide text-slate-500">
              {CATEGORY_NAMES[g.category]}
            </h3>
            <ul className="space-y-1">
              {g.entries.map((e) => (
                <LibraryEntryItem
                  key={e.block.type}
                  entry={e}
                  open={e.open}
                  robotName={robotName}
                  unsupported={unsupported.has(e.block.type)}
                  onAdd={onAdd}
                />
              ))}
            </ul>
          </section>
        ))}
        {groups.length === 0 && <p className="text-sm text-slate-500">No block matches “{query}”.</p>}
      </div>
    </section>
  );
});

/** A block and, behind a disclosure, the robot's own actions that do the same. */
function LibraryEntryItem({
  entry,
  open,
  robotName,
  unsupported,
  onAdd,
}: {
  entry: LibraryEntry;
  /** A search found one of the variants: shown without asking. */
  open: boolean;
  robotName: string;
  unsupported: boolean;
  onAdd: (block: Block) => void;
}) {
  const [expanded, setExpanded] = useState(false);
  const { block, variants } = entry;
  const shown = open || expanded;
  const Chevron = shown ? ChevronDown : ChevronRight;
  return (
    <li>
      <div className="flex items-stretch gap-1">
        <LibraryBlock block={block} unsupported={unsupported} onAdd={onAdd} />
        {variants.length > 0 && (
          <button
            type="button"
            aria-expanded={shown}
            // Its name starts with the number it shows, so the two never disagree (WCAG 2.5.3).
            aria-label={`${variants.length} ${variants.length === 1 ? "version" : "versions"} of ${block.name} on ${robotName}`}
            title={`${robotName}'s own versions of ${block.name}`}
            onClick={() => setExpanded(!shown)}
            className="flex shrink-0 items-center gap-0.5 rounded-md border border-slate-200 bg-white px-1.5 text-xs text-slate-600 hover:border-brand-500 focus:outline-none focus:ring-2 focus:ring-brand-500/40"
          >
            <Chevron className="h-3.5 w-3.5" aria-hidden />
            {variants.length}
          </button>
        )}
      </div>
      {shown && variants.length > 0 && (
        <div className="ml-3 mt-1 border-l-2 border-slate-200 pl-2">
          <p className="text-[11px] text-slate-600">On {robotName}:</p>
          <ul aria-label={`Versions of ${block.name} on ${robotName}`} className="space-y-1">
            {variants.map((v) => (
              <li key={v.type}>
                <LibraryBlock block={v} unsupported={false} onAdd={onAdd} />
              </li>
            ))}
          </ul>
        </div>
      )}
    </li>
  );
}

const LibraryBlock = memo(function LibraryBlock({
  block,
  unsupported,
  onAdd,
}: {
  block: Block;
  unsupported: boolean;
  onAdd: (block: Block) => void;
}) {
  const { attributes, listeners, setNodeRef, isDragging } = useDraggable({
    id: libraryDragId(block.type),
    data: { block },
  });
  return (
    <button
      ref={setNodeRef}
      {...attributes}
      {...listeners}
      type="button"
      data-block={block.type}
      title={block.description}
      onClick={() => onAdd(block)}
      onKeyDown={(e) => {
        if (e.key === "Enter" || e.key === " ") {
          e.preventDefault();
          onAdd(block);
        }
      }}
      className={`w-full min-w-0 cursor-grab rounded-md border bg-white px-2.5 py-1.5 text-left text-sm shadow-sm hover:border-brand-500 focus:outline-none focus:ring-2 focus:ring-brand-500/40 ${isDragging ? "opacity-50" : ""} ${unsupported ? "border-dashed border-amber-400 text-slate-500" : "border-slate-200"}`}
    >
      <span className="font-medium">{block.name}</span>
      {unsupported && <span className="ml-1 text-xs text-amber-700">(not on this robot)</span>}
    </button>
  );
});
