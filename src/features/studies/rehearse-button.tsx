"use client";
// "Rehearse" an experiment's draft, as one of the study's conditions that run
// it when there are any (their variants), or as the shared design.
import { useState } from "react";
import { Button } from "@/ui/button";

export function RehearseButton({
  experiment,
  conditions,
  pending,
  onRehearse,
}: {
  experiment: { id: string; name: string };
  /** The names of the conditions that run this experiment. */
  conditions: string[];
  pending: boolean;
  onRehearse: (input: { experimentId: string; condition?: string }) => void;
}) {
  const [condition, setCondition] = useState("");
  return (
    <span className="inline-flex items-center gap-1">
      {conditions.length > 0 && (
        <select
          aria-label={`Rehearse ${experiment.name} as`}
          className="rounded-md border border-slate-300 bg-white px-1 py-1 text-xs"
          value={condition}
          onChange={(e) => setCondition(e.target.value)}
        >
          <option value="">the shared design</option>
          {conditions.map((c) => (
            <option key={c} value={c}>
              {c}
            </option>
          ))}
        </select>
      )}
      <Button
        variant="ghost"
        size="sm"
        aria-label={`Rehearse ${experiment.name}`}
        disabled={pending}
        onClick={() => onRehearse({ experimentId: experiment.id, ...(condition && { condition }) })}
      >
        Rehearse
      </Button>
    </span>
  );
}
