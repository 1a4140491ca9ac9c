"use client";
// A "Wait for" in the designer: the robot's events it waits for, picked from
// what the experiment's robot senses (its plugin's events), each with where
// it leads, and a time limit with its own way on. The wizard's go on needs no
// setting: it takes what follows the block, then the step's own "Then".
import { Plus, X } from "lucide-react";
import { commands } from "@/core/designer/model";
import type { Command } from "@/core/designer/history";
import type { DesignAction, DesignDraft } from "@/core/designer/types";
import type { RobotEvent } from "@/core/plugins";
import { awaitedEvents, type AwaitedEvent } from "@/core/protocol/flow";
import { newId } from "@/lib/new-id";
import { Button } from "@/ui/button";
import { Field, NativeSelect } from "@/ui/field";
import { afterOf, afterValue, LeadsToOptions } from "./then-field";
import { TimeLimitField } from "./time-limit-field";

export function WaitEditor({
  draft,
  stepId,
  action,
  events,
  run,
}: {
  draft: DesignDraft;
  stepId: string;
  action: DesignAction;
  /** What the experiment's robot senses; empty without its plugin. */
  events: RobotEvent[];
  run: (c: Command) => void;
}) {
  const awaited = awaitedEvents(action);
  const set = (next: AwaitedEvent[]) => run(commands.setParameter(action.id, "events", next));
  const change = (id: string, part: Partial<AwaitedEvent>) =>
    set(awaited.map((e) => (e.id === id ? { ...e, ...part } : e)));
  const unused = events.find((e) => !awaited.some((a) => a.event === e.id));
  return (
    <div className="space-y-3">
      <fieldset className="space-y-3">
        <legend className="text-sm font-medium text-slate-700">Events the trial waits for</legend>
        {events.length === 0 && (
          <p className="text-sm text-amber-800">The experiment's robot declares nothing it senses.</p>
        )}
        {awaited.map((e, i) => (
          <div key={e.id} className="space-y-1 rounded border border-slate-200 p-2">
            <div className="flex items-end gap-1">
              <Field label={`Event ${i + 1}`}>
                {(p) => (
                  <NativeSelect {...p} value={e.event} onChange={(x) => change(e.id, { event: x.target.value })}>
                    {events.map((robotEvent) => (
                      <option key={robotEvent.id} value={robotEvent.id}>
                        {robotEvent.name}
                      </option>
                    ))}
                    {!events.some((robotEvent) => robotEvent.id === e.event) && (
                      <option value={e.event}>{e.event} (the robot does not sense it)</option>
                    )}
                  </NativeSelect>
                )}
              </Field>
              <Button
                variant="ghost"
                size="sm"
                aria-label={`Remove event ${i + 1}`}
                onClick={() => set(awaited.filter((x) => x.id !== e.id))}
              >
                <X className="h-4 w-4" aria-hidden />
              </Button>
            </div>
            <Field label="Then">
              {(p) => (
                <NativeSelect
                  {...p}
                  value={afterValue(e.after)}
                  onChange={(x) => change(e.id, { after: afterOf(x.target.value, null) })}
                >
                  <LeadsToOptions draft={draft} stepId={stepId} value={afterValue(e.after)} />
                </NativeSelect>
              )}
            </Field>
          </div>
        ))}
        {unused && (
          <Button
            variant="secondary"
            size="sm"
            onClick={() => set([...awaited, { id: newId(), event: unused.id, after: { to: "next" } }])}
          >
            <Plus className="h-4 w-4" aria-hidden /> Add an event
          </Button>
        )}
      </fieldset>
      <TimeLimitField
        draft={draft}
        stepId={stepId}
        limit={action.timeLimit}
        label="Nothing sensed in (seconds)"
        hint="Counted once the actions before this wait are done. Leave empty to wait until an event or the wizard's go on."
        onChange={(limit) => run(commands.setAnswerTimeLimit(action.id, limit))}
      />
      <p className="text-xs text-slate-600">
        The wizard can always go on (key G): the trial then carries on with what follows this block, then the step's
        “Then”.
      </p>
    </div>
  );
}
