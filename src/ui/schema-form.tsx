"use client";
// A form generated from an action's parameter JSON Schema: enums as choices,
// numbers with their range, required fields marked, errors inline. Nobody
// types JSON.
import type { ParameterProblem, ParameterSchema } from "@/core/plugins";
import { Field, Input, NativeSelect } from "./field";

type Values = Record<string, unknown>;

export function SchemaForm({
  schema,
  value,
  onChange,
  problems = [],
}: {
  schema: ParameterSchema;
  value: Values;
  onChange: (v: Values) => void;
  problems?: ParameterProblem[];
}) {
  const entries = Object.entries(schema.properties);
  if (!entries.length) return <p className="text-sm text-slate-500">No settings.</p>;
  return (
    <div className="space-y-3">
      {entries.map(([name, property]) => {
        const p = property as {
          type: string;
          title?: string;
          description?: string;
          enum?: unknown[];
          minimum?: number;
          maximum?: number;
          default?: unknown;
        };
        const label = p.title ?? name;
        const error = problems.find((x) => x.parameter === name)?.message;
        const required = schema.required?.includes(name);
        const set = (v: unknown) => onChange({ ...value, [name]: v });
        const current = value[name] ?? p.default ?? "";
        const range =
          p.minimum !== undefined || p.maximum !== undefined
            ? `from ${p.minimum ?? "…"} to ${p.maximum ?? "…"}`
            : undefined;
        return (
          <Field key={name} label={label} required={required} error={error} hint={p.description ?? range}>
            {(a) =>
              p.enum ? (
                <NativeSelect {...a} value={String(current)} onChange={(e) => set(e.target.value)}>
                  <option value="">{required ? "Choose…" : "—"}</option>
                  {p.enum.map((option) => (
                    <option key={String(option)}>{String(option)}</option>
                  ))}
                </NativeSelect>
              ) : p.type === "boolean" ? (
                <input
                  {...a}
                  type="checkbox"
                  className="h-4 w-4"
                  checked={Boolean(current)}
                  onChange={(e) => set(e.target.checked)}
                />
              ) : p.type === "number" || p.type === "integer" ? (
                <Input
                  {...a}
                  type="number"
                  min={p.minimum}
                  max={p.maximum}
                  step={p.type === "integer" ? 1 : "any"}
                  value={String(current)}
                  onChange={(e) => set(e.target.value === "" ? undefined : Number(e.target.value))}
                />
              ) : (
                <Input {...a} value={String(current)} onChange={(e) => set(e.target.value)} />
              )
            }
          </Field>
        );
      })}
    </div>
  );
}
