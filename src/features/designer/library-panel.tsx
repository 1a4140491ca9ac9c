"use client";
// The block library: searchable, grouped, each block dragged into a step or
// added to the selected step with Enter (the keyboard way).
import { useDraggable } from "@dnd-kit/core";
import { Search } from "lucide-react";
import { memo, useMemo, useState } from "react";
import type { Block, BlockCategory } from "@/core/designer/blocks";
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
  blocks,
  unsupported,
  onAdd,
}: {
  blocks: Block[];
  unsupported: Set<string>;
  onAdd: (block: Block) => void;
}) {
  const [query, setQuery] = useState("");
  const groups = useMemo(() => {
    const q = query.trim().toLowerCase();
    const shown = blocks.filter(
      (b) =>
        !q ||
        b.name.toLowerCase().includes(q) ||
        b.type.toLowerCase().includes(q) ||
        b.description.toLowerCase().includes(q),
    );
    return (Object.keys(CATEGORY_NAMES) as BlockCategory[])
      .map((c) => ({ category: c, blocks: shown.filter((b) => b.category === c) }))
      .filter((g) => g.blocks.length);
  }, [blocks, query]);
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
              {g.blocks.map((b) => (
                <LibraryBlock key={b.type} block={b} unsupported={unsupported.has(b.type)} onAdd={onAdd} />
              ))}
            </ul>
          </section>
        ))}
        {groups.length === 0 && <p className="text-sm text-slate-500">No block matches “{query}”.</p>}
      </div>
    </section>
  );
});

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
    <li>
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
        className={`w-full cursor-grab rounded-md border bg-white px-2.5 py-1.5 text-left text-sm shadow-sm hover:border-brand-500 focus:outline-none focus:ring-2 focus:ring-brand-500/40 ${isDragging ? "opacity-50" : ""} ${unsupported ? "border-dashed border-amber-400 text-slate-500" : "border-slate-200"}`}
      >
        <span className="font-medium">{block.name}</span>
        {unsupported && <span className="ml-1 text-xs text-amber-700">(not on this robot)</span>}
      </button>
    </li>
  );
});
