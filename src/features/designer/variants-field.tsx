"use client";
// An action's "Varies by condition": one editor per condition of the study
// that runs this experiment, side by side. A condition left unticked runs the
// action as it is designed above; a ticked one starts from a copy of it.
import type { Block } from "@/core/designer/blocks";
import { commands } from "@/core/designer/model";
import type { Command } from "@/core/designer/history";
import type { DesignAction } from "@/core/designer/types";
import type { ReactNode } from "react";
import { SchemaForm } from "@/ui/schema-form";

export function VariantsField({
  action,
  block,
  conditions,
  run,
}: {
  action: DesignAction;
  block: Block;
  conditions: string[];
  run: (c: Command) => void;
}) {
  if (!conditions.length) return null;
  const variants = action.variants ?? {};
  return (
    <fieldset className="space-y-2">
      <legend className="text-sm font-medium text-slate-700">Varies by condition</legend>
      <div className="grid gap-2" style={{ gridTemplateColumns: `repeat(${conditions.length}, minmax(0, 1fr))` }}>
        {conditions.map((condition) => {
          const variant = variants[condition];
          const set = (next: typeof variant | null) => run(commands.setVariant(action.id, condition, next ?? null));
          return (
            <ConditionColumn
              key={condition}
              condition={condition}
              own={Boolean(variant)}
              ownLabel={`Own in “${condition}”`}
              onOwn={(own) => set(own ? { parameters: action.parameters } : null)}
            >
              {variant ? (
                <SchemaForm
                  schema={block.parameterSchema}
                  value={variant.parameters}
                  onChange={(parameters) => set({ ...variant, parameters })}
                />
              ) : (
                <p className="text-xs text-slate-500">Runs the action as above.</p>
              )}
            </ConditionColumn>
          );
        })}
      </div>
    </fieldset>
  );
}

/** One condition's column of a "Varies by condition": whether it has its own, and what it runs. */
export function ConditionColumn({
  condition,
  own,
  ownLabel,
  onOwn,
  children,
}: {
  condition: string;
  own: boolean;
  ownLabel: string;
  onOwn: (own: boolean) => void;
  children: ReactNode;
}) {
  return (
    <fieldset aria-label={`In “${condition}”`} className="min-w-0 space-y-2 rounded border border-slate-200 p-2">
      <label className="flex items-center gap-2 text-sm">
        <input type="checkbox" className="h-4 w-4" checked={own} onChange={(e) => onOwn(e.target.checked)} />
        {ownLabel}
      </label>
      {children}
    </fieldset>
  );
}
