"use client";
// What the participant sees, on a tablet or their own device: no account,
// large controls, every answer kept as a draft as it is given, one submit.
import { useMutation, useQuery } from "@tanstack/react-query";
import { CheckCircle2 } from "lucide-react";
import { useEffect, useRef, useState } from "react";
import type { Answer, Answers } from "@/core/questionnaires/answers";
import type { Item } from "@/core/questionnaires/definition";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Input, Textarea } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Card, Spinner } from "@/ui/surface";

const DRAFT_DELAY_MS = 600;

export function ParticipantForm({ token }: { token: string }) {
  const trpc = useTRPC();
  const form = useQuery(
    trpc.form.open.queryOptions({ token }, { retry: false, refetchOnWindowFocus: false, staleTime: Infinity }),
  );
  const [answers, setAnswers] = useState<Answers | null>(null);
  const save = useMutation(trpc.form.save.mutationOptions());
  const submit = useMutation(trpc.form.submit.mutationOptions());
  const dirty = useRef(false);

  useEffect(() => {
    if (form.data && answers === null) setAnswers(form.data.answers);
  }, [form.data, answers]);

  // Every change is saved as a draft a moment later: a reload or a lost tab keeps it.
  // biome-ignore lint/correctness/useExhaustiveDependencies: keyed on the answers alone (see below)
  useEffect(() => {
    if (!answers || !dirty.current || submit.isSuccess) return;
    const timer = setTimeout(() => save.mutate({ token, answers }), DRAFT_DELAY_MS);
    return () => clearTimeout(timer);
    // Keyed on the answers alone: the mutation object changes on every render.
  }, [answers, token, submit.isSuccess]);

  if (form.isPending) return <Spinner label="Opening the questionnaire…" />;
  if (form.error) return <Problem error={form.error} />;
  if (submit.isSuccess) {
    return (
      <Card className="p-8 text-center">
        <CheckCircle2 className="mx-auto h-10 w-10 text-emerald-600" aria-hidden />
        <h1 className="mt-3 text-xl font-semibold">Thank you!</h1>
        <p className="mt-1 text-slate-600">Your answers have been submitted. You can hand the device back now.</p>
      </Card>
    );
  }
  const { definition } = form.data;
  const set = (id: string, value: Answer | undefined) => {
    dirty.current = true;
    setAnswers((a) => {
      const next = { ...(a ?? {}) };
      if (value === undefined) delete next[id];
      else next[id] = value;
      return next;
    });
  };
  return (
    <form
      className="space-y-6"
      onSubmit={(e) => {
        e.preventDefault();
        submit.mutate({ token, answers: answers ?? {} });
      }}
    >
      <header>
        <p className="text-sm text-slate-500">{form.data.studyTitle}</p>
        <h1 className="text-2xl font-semibold">{definition.title}</h1>
        {definition.instructions && (
          <p className="mt-2 whitespace-pre-wrap text-slate-700">{definition.instructions}</p>
        )}
      </header>
      {definition.sections.map((section) => (
        <section key={section.id} className="space-y-4">
          {section.title && <h2 className="text-lg font-semibold">{section.title}</h2>}
          {section.items.map((item, i) => (
            <Card key={item.id} className="p-4">
              <ItemField
                item={item}
                number={i + 1}
                value={answers?.[item.id]}
                onChange={(v) => set(item.id, v)}
                agreement={form.data.consentAgreement}
              />
            </Card>
          ))}
        </section>
      ))}
      <Problem error={submit.error} />
      <div className="flex items-center gap-4">
        <Button type="submit" size="lg" disabled={submit.isPending}>
          Submit answers
        </Button>
        <span role="status" className="text-sm text-slate-500">
          {save.isPending
            ? "Saving…"
            : save.isSuccess
              ? "Your answers so far are saved."
              : save.error
                ? "Not saved: check your connection."
                : ""}
        </span>
      </div>
    </form>
  );
}

function ItemField({
  item,
  number,
  value,
  onChange,
  agreement,
}: {
  item: Item;
  number: number;
  value: Answer | undefined;
  onChange: (v: Answer | undefined) => void;
  /** The study's words beside the consent checkbox. */
  agreement: string;
}) {
  const label = (
    <legend className="mb-3 font-medium">
      <span className="mr-1 text-slate-500">{number}.</span>
      {item.kind === "consent" ? "Consent" : item.text}
      {item.required && (
        <span className="ml-0.5 text-red-600" aria-hidden>
          *
        </span>
      )}
    </legend>
  );
  switch (item.kind) {
    case "likert": {
      const points = Array.from({ length: item.scale.max - item.scale.min + 1 }, (_, i) => item.scale.min + i);
      return (
        <fieldset>
          {label}
          <div className="flex flex-wrap items-center gap-2">
            <span className="w-28 text-right text-sm text-slate-500">{item.scale.minLabel}</span>
            {points.map((p) => (
              <label
                key={p}
                className="flex cursor-pointer flex-col items-center gap-1 rounded-md border border-slate-200 px-3 py-2 has-[:checked]:border-brand-500 has-[:checked]:bg-brand-50"
              >
                <input
                  type="radio"
                  name={item.id}
                  value={p}
                  checked={value === p}
                  onChange={() => onChange(p)}
                  aria-label={`${item.text}: ${p}`}
                  className="h-5 w-5"
                />
                <span className="text-sm">{p}</span>
              </label>
            ))}
            <span className="w-28 text-sm text-slate-500">{item.scale.maxLabel}</span>
          </div>
        </fieldset>
      );
    }
    case "single":
    case "multiple":
      return (
        <fieldset>
          {label}
          <div className="space-y-2">
            {item.options.map((o) => {
              const chosen = item.kind === "single" ? value === o : Array.isArray(value) && value.includes(o);
              const toggle = () => {
                if (item.kind === "single") return onChange(o);
                const list = Array.isArray(value) ? value : [];
                onChange(chosen ? list.filter((x) => x !== o) : [...list, o]);
              };
              return (
                <label key={o} className="flex items-center gap-2">
                  <input
                    type={item.kind === "single" ? "radio" : "checkbox"}
                    name={item.id}
                    checked={chosen}
                    onChange={toggle}
                    className="h-5 w-5"
                  />
                  {o}
                </label>
              );
            })}
          </div>
        </fieldset>
      );
    case "consent":
      return (
        <fieldset>
          {label}
          <p className="mb-3 whitespace-pre-wrap rounded-md bg-slate-50 p-3 text-sm text-slate-700">{item.text}</p>
          <label className="flex items-center gap-2 font-medium">
            <input
              type="checkbox"
              checked={value === true}
              onChange={(e) => onChange(e.target.checked)}
              className="h-5 w-5"
            />
            {agreement}
          </label>
        </fieldset>
      );
    case "number":
      return (
        <fieldset>
          {label}
          <Input
            type="number"
            aria-label={item.text}
            min={item.min}
            max={item.max}
            value={typeof value === "number" ? value : ""}
            onChange={(e) => onChange(e.target.value === "" ? undefined : Number(e.target.value))}
            className="max-w-40"
          />
        </fieldset>
      );
    default:
      return (
        <fieldset>
          {label}
          {item.kind === "long_text" ? (
            <Textarea
              aria-label={item.text}
              value={typeof value === "string" ? value : ""}
              onChange={(e) => onChange(e.target.value)}
            />
          ) : (
            <Input
              aria-label={item.text}
              value={typeof value === "string" ? value : ""}
              onChange={(e) => onChange(e.target.value)}
            />
          )}
        </fieldset>
      );
  }
}
