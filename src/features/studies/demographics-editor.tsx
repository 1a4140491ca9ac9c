"use client";
// The demographic questions a study asks of each participant. Answers are
// optional for participants; the key is made from the question's wording.
import { Plus, X } from "lucide-react";
import { DEMOGRAPHIC_TYPES, type DemographicField } from "@/core/studies/settings";
import { Button } from "@/ui/button";
import { Input, NativeSelect } from "@/ui/field";

const keyOf = (label: string, taken: string[]) => {
  const base = (
    label
      .toLowerCase()
      .replace(/[^a-z0-9]+/g, "_")
      .replace(/^_+|_+$/g, "")
      .replace(/^(\d)/, "q_$1") || "question"
  ).slice(0, 30);
  let key = base;
  for (let n = 2; taken.includes(key); n++) key = `${base}_${n}`;
  return key;
};

export function DemographicsEditor({
  fields,
  onChange,
}: {
  fields: DemographicField[];
  onChange: (f: DemographicField[]) => void;
}) {
  const set = (i: number, change: Partial<DemographicField>) =>
    onChange(fields.map((f, j) => (j === i ? { ...f, ...change } : f)));
  return (
    <fieldset className="space-y-2 rounded-md border border-slate-200 p-3">
      <legend className="px-1 text-sm font-medium text-slate-700">Demographic questions</legend>
      {fields.length === 0 && (
        <p className="text-xs text-slate-500">None. Participants are known by their code only.</p>
      )}
      {fields.map((f, i) => (
        <div key={f.key} className="flex flex-wrap items-center gap-2">
          <Input
            aria-label={`Question ${i + 1}`}
            className="w-48"
            value={f.label}
            onChange={(e) => set(i, { label: e.target.value })}
          />
          <NativeSelect
            aria-label={`Answer type of question ${i + 1}`}
            className="w-32"
            value={f.type}
            onChange={(e) => set(i, { type: e.target.value as DemographicField["type"] })}
          >
            {DEMOGRAPHIC_TYPES.map((t) => (
              <option key={t}>{t}</option>
            ))}
          </NativeSelect>
          {f.type === "choice" && (
            <Input
              aria-label={`Choices of question ${i + 1}`}
              className="w-56"
              placeholder="choices, comma-separated"
              value={f.options.join(", ")}
              onChange={(e) =>
                set(i, {
                  options: e.target.value
                    .split(",")
                    .map((o) => o.trim())
                    .filter(Boolean),
                })
              }
            />
          )}
          <Button
            variant="ghost"
            size="sm"
            aria-label={`Remove question ${i + 1}`}
            onClick={() => onChange(fields.filter((_, j) => j !== i))}
          >
            <X className="h-4 w-4" aria-hidden />
          </Button>
        </div>
      ))}
      <Button
        variant="secondary"
        size="sm"
        onClick={() => {
          const label = `Question ${fields.length + 1}`;
          onChange([
            ...fields,
            {
              key: keyOf(
                label,
                fields.map((f) => f.key),
              ),
              label,
              type: "text",
              options: [],
            },
          ]);
        }}
      >
        <Plus className="h-4 w-4" aria-hidden /> Add a question
      </Button>
    </fieldset>
  );
}
