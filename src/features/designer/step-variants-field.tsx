"use client";
// A step's "Varies by condition": beside the step's shared actions, one column
// per condition of the study that runs this experiment. A ticked condition has
// its own actions (a copy of the shared ones to start from), each with its
// main text to edit, its other settings under "More settings", and a way to
// remove it; an unticked one runs the shared.
import { X } from "lucide-react";
import { type Block, OWN_EDITORS } from "@/core/designer/blocks";
import { changedParameters } from "@/core/designer/changed-parameters";
import { actionName, FREE_TEXT_PARAMETERS } from "@/core/designer/action-name";
import { commands } from "@/core/designer/model";
import type { Command } from "@/core/designer/history";
import type { DesignStep } from "@/core/designer/types";
import { Button } from "@/ui/button";
import { Input } from "@/ui/field";
import { SchemaForm } from "@/ui/schema-form";
import { ConditionColumn } from "./variants-field";

type Action = { id: string; type: string; name: string; parameters: Record<string, unknown> };

export function StepVariantsField({
  step,
  conditions,
  blockFor,
  run,
}: {
  step: DesignStep;
  conditions: string[];
  blockFor: (type: string) => Block | undefined;
  run: (c: Command) => void;
}) {
  if (!conditions.length) return null;
  const nameOf = (action: Action) => actionName(action, { [action.type]: blockFor(action.type)?.name ?? action.type });
  return (
    <fieldset className="space-y-2">
      <legend className="text-sm font-medium text-slate-700">Varies by condition</legend>
      {/* Side by side while each column has room for a line of text; under each other in a narrow panel. */}
      <div className="grid grid-cols-[repeat(auto-fit,minmax(9rem,1fr))] gap-2">
        <fieldset aria-label="Shared" className="min-w-0 space-y-1 rounded border border-slate-200 p-2">
          <p className="text-sm font-medium">Shared</p>
          <ActionNames actions={step.actions} nameOf={nameOf} />
        </fieldset>
        {conditions.map((condition) => {
          const variant = step.variants?.[condition];
          return (
            <ConditionColumn
              key={condition}
              condition={condition}
              own={Boolean(variant)}
              ownLabel={`Own actions in “${condition}”`}
              onOwn={(own) => run(commands.setStepVariant(step.id, condition, own))}
            >
              {!variant ? (
                <p className="text-xs text-slate-500">Runs the step's actions.</p>
              ) : !variant.actions.length ? (
                <p className="text-xs text-slate-500">No actions: the step does nothing in this condition.</p>
              ) : (
                <ol className="space-y-2">
                  {variant.actions.map((action, i) => {
                    const text = FREE_TEXT_PARAMETERS.find(
                      (k) => blockFor(action.type)?.parameterSchema.properties?.[k],
                    );
                    const label = `${nameOf(action)}, action ${i + 1} in “${condition}”`;
                    return (
                      <li key={action.id} className="space-y-1">
                        <div className="flex items-center gap-1">
                          <span className="min-w-0 flex-1 truncate text-xs text-slate-700">{nameOf(action)}</span>
                          <Button
                            variant="ghost"
                            size="sm"
                            aria-label={`Remove ${label}`}
                            onClick={() => run(commands.removeStepVariantAction(step.id, condition, action.id))}
                          >
                            <X className="h-4 w-4" aria-hidden />
                          </Button>
                        </div>
                        {text && (
                          <Input
                            aria-label={`Text of ${label}`}
                            value={String(action.parameters[text] ?? "")}
                            onChange={(e) =>
                              run(commands.setStepVariantParameter(step.id, condition, action.id, text, e.target.value))
                            }
                          />
                        )}
                        <MoreSettings
                          block={blockFor(action.type)}
                          action={action}
                          besides={text}
                          label={label}
                          onChange={(name, value) =>
                            run(commands.setStepVariantParameter(step.id, condition, action.id, name, value))
                          }
                        />
                      </li>
                    );
                  })}
                </ol>
              )}
            </ConditionColumn>
          );
        })}
      </div>
    </fieldset>
  );
}

function ActionNames({ actions, nameOf }: { actions: Action[]; nameOf: (a: Action) => string }) {
  if (!actions.length) return <p className="text-xs text-slate-500">No actions.</p>;
  return (
    <ol className="space-y-1 text-xs text-slate-700">
      {actions.map((action) => (
        <li key={action.id} className="truncate">
          {nameOf(action)}
        </li>
      ))}
    </ol>
  );
}

/** An own action's settings beside its main text, folded away: the column stays a list of actions to read. */
function MoreSettings({
  block,
  action,
  besides,
  label,
  onChange,
}: {
  block: Block | undefined;
  action: Action;
  besides: string | undefined;
  label: string;
  onChange: (name: string, value: unknown) => void;
}) {
  if (!block || OWN_EDITORS.has(action.type)) return null;
  const { [besides ?? ""]: _, ...properties } = block.parameterSchema.properties ?? {};
  if (!Object.keys(properties).length) return null;
  return (
    <details className="text-xs">
      <summary className="cursor-pointer text-slate-600" aria-label={`More settings of ${label}`}>
        More settings
      </summary>
      <div className="pt-2">
        <SchemaForm
          schema={{ ...block.parameterSchema, properties }}
          value={action.parameters}
          onChange={(values) => {
            for (const [name, value] of changedParameters(action.parameters, values)) onChange(name, value);
          }}
        />
      </div>
    </details>
  );
}
