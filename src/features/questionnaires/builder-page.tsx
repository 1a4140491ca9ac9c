"use client";
// The questionnaire builder: sections of questions, each edited in place.
// Every edit is one of the builder's pure functions; Save keeps the draft,
// Publish freezes it as the next version participants see.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { ArrowDown, ArrowUp, Plus, Trash2 } from "lucide-react";
import Link from "next/link";
import { useEffect, useState } from "react";
import { builder } from "@/core/questionnaires/builder";
import type { Definition, Item, ItemKind } from "@/core/questionnaires/definition";
import { newId } from "@/lib/new-id";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect, Textarea } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Badge, Card, Spinner } from "@/ui/surface";

const KINDS: Array<[ItemKind, string]> = [
  ["likert", "Likert scale"],
  ["single", "Single choice"],
  ["multiple", "Multiple choice"],
  ["short_text", "Short text"],
  ["long_text", "Long text"],
  ["number", "Number"],
  ["consent", "Consent (with its text)"],
];

export function QuestionnaireBuilderPage({ questionnaireId }: { questionnaireId: string }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const loaded = useQuery(trpc.questionnaires.get.queryOptions({ questionnaireId }, { refetchOnWindowFocus: false }));
  const [definition, setDefinition] = useState<Definition | null>(null);
  const [name, setName] = useState("");
  const [changed, setChanged] = useState(false);
  const save = useMutation(trpc.questionnaires.save.mutationOptions({ onSuccess: () => setChanged(false) }));
  const publish = useMutation(
    trpc.questionnaires.publish.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.questionnaires.list.queryKey() }),
    }),
  );

  useEffect(() => {
    if (loaded.data && !definition) {
      setDefinition(loaded.data.draft);
      setName(loaded.data.name);
    }
  }, [loaded.data, definition]);

  if (loaded.isPending || (!definition && !loaded.error)) return <Spinner />;
  if (loaded.error || !definition) return <Problem error={loaded.error} />;
  const edit = (next: Definition) => {
    setDefinition(next);
    setChanged(true);
  };
  const saveDraft = () => save.mutateAsync({ questionnaireId, name, definition });
  return (
    <div className="space-y-6">
      <div className="flex flex-wrap items-center gap-3">
        <Link href={`/studies/${loaded.data!.studyId}`} className="text-sm text-slate-500 hover:text-slate-800">
          ← Study
        </Link>
        <h1 className="text-2xl font-semibold">Questionnaire</h1>
        {definition.instrument && <Badge tone="blue">standard instrument: scored as published</Badge>}
        <div className="ml-auto flex items-center gap-2">
          <span role="status" className="text-sm text-slate-500">
            {changed ? "Unsaved changes" : save.isSuccess ? "Saved" : ""}
          </span>
          <Button variant="secondary" disabled={save.isPending} onClick={() => void saveDraft()}>
            Save draft
          </Button>
          <Button
            disabled={publish.isPending}
            onClick={async () => {
              await saveDraft();
              publish.mutate({ questionnaireId });
            }}
          >
            Publish
          </Button>
        </div>
      </div>
      <Problem error={save.error ?? publish.error} />
      {publish.data && (
        <p className="text-sm text-emerald-800">
          Published version {publish.data.version}. New links show this version; answers given before keep theirs.
        </p>
      )}
      <Card className="space-y-3 p-5">
        <Field label="Name in the study">
          {(p) => <Input {...p} value={name} onChange={(e) => (setName(e.target.value), setChanged(true))} />}
        </Field>
        <Field label="Title the participant sees">
          {(p) => (
            <Input
              {...p}
              value={definition.title}
              onChange={(e) => edit(builder.setDetails(definition, { title: e.target.value }))}
            />
          )}
        </Field>
        <Field label="Instructions">
          {(p) => (
            <Textarea
              {...p}
              value={definition.instructions}
              onChange={(e) => edit(builder.setDetails(definition, { instructions: e.target.value }))}
            />
          )}
        </Field>
      </Card>
      {definition.sections.map((section, si) => (
        <Card key={section.id} className="space-y-4 p-5">
          <div className="flex flex-wrap items-end gap-3">
            <div className="w-72">
              <Field label={`Section ${si + 1} title`}>
                {(p) => (
                  <Input
                    {...p}
                    value={section.title}
                    onChange={(e) => edit(builder.updateSection(definition, section.id, { title: e.target.value }))}
                  />
                )}
              </Field>
            </div>
            <label className="mb-2 flex items-center gap-2 text-sm">
              <input
                type="checkbox"
                className="h-4 w-4"
                checked={section.randomize}
                onChange={(e) => edit(builder.updateSection(definition, section.id, { randomize: e.target.checked }))}
              />
              Show its questions in a random order for each participant
            </label>
            {definition.sections.length > 1 && (
              <Button
                variant="ghost"
                size="sm"
                className="mb-1 ml-auto text-red-700"
                onClick={() => edit(builder.removeSection(definition, section.id))}
              >
                Remove section
              </Button>
            )}
          </div>
          <ol className="space-y-3">
            {section.items.map((item, ii) => (
              <li key={item.id} className="rounded-md border border-slate-200 p-3">
                <ItemEditor
                  item={item}
                  number={ii + 1}
                  onChange={(changes) => edit(builder.updateItem(definition, item.id, changes))}
                />
                <div className="mt-2 flex gap-1">
                  <Button
                    variant="ghost"
                    size="sm"
                    aria-label={`Move question ${ii + 1} up`}
                    onClick={() => edit(builder.moveItem(definition, item.id, -1))}
                  >
                    <ArrowUp className="h-4 w-4" aria-hidden />
                  </Button>
                  <Button
                    variant="ghost"
                    size="sm"
                    aria-label={`Move question ${ii + 1} down`}
                    onClick={() => edit(builder.moveItem(definition, item.id, 1))}
                  >
                    <ArrowDown className="h-4 w-4" aria-hidden />
                  </Button>
                  <Button
                    variant="ghost"
                    size="sm"
                    className="ml-auto text-red-700"
                    aria-label={`Remove question ${ii + 1}`}
                    onClick={() => edit(builder.removeItem(definition, item.id))}
                  >
                    <Trash2 className="h-4 w-4" aria-hidden />
                  </Button>
                </div>
              </li>
            ))}
          </ol>
          <AddQuestion onAdd={(kind) => edit(builder.addItem(definition, section.id, kind, newId()))} />
        </Card>
      ))}
      <Button variant="secondary" onClick={() => edit(builder.addSection(definition, "", newId()))}>
        <Plus className="h-4 w-4" aria-hidden /> Add section
      </Button>
    </div>
  );
}

function AddQuestion({ onAdd }: { onAdd: (kind: ItemKind) => void }) {
  const [kind, setKind] = useState<ItemKind>("likert");
  return (
    <div className="flex items-center gap-2">
      <NativeSelect
        aria-label="Kind of question"
        className="w-56"
        value={kind}
        onChange={(e) => setKind(e.target.value as ItemKind)}
      >
        {KINDS.map(([k, label]) => (
          <option key={k} value={k}>
            {label}
          </option>
        ))}
      </NativeSelect>
      <Button variant="secondary" onClick={() => onAdd(kind)}>
        <Plus className="h-4 w-4" aria-hidden /> Add question
      </Button>
    </div>
  );
}

function ItemEditor({
  item,
  number,
  onChange,
}: {
  item: Item;
  number: number;
  onChange: (changes: Partial<Item>) => void;
}) {
  const kindName = KINDS.find(([k]) => k === item.kind)![1];
  return (
    <div className="space-y-2">
      <div className="flex items-center gap-2 text-xs text-slate-500">
        <span className="font-semibold">Question {number}</span> · {kindName}
        <label className="ml-auto flex items-center gap-1">
          <input type="checkbox" checked={item.required} onChange={(e) => onChange({ required: e.target.checked })} />{" "}
          required
        </label>
      </div>
      <Textarea
        aria-label={`Text of question ${number}`}
        className="min-h-12"
        value={item.text}
        onChange={(e) => onChange({ text: e.target.value })}
      />
      {item.kind === "likert" && (
        <div className="flex flex-wrap gap-2 text-sm">
          <Input
            aria-label="Lowest point"
            type="number"
            className="w-20"
            value={item.scale.min}
            onChange={(e) => onChange({ scale: { ...item.scale, min: Number(e.target.value) } })}
          />
          <Input
            aria-label="Highest point"
            type="number"
            className="w-20"
            value={item.scale.max}
            onChange={(e) => onChange({ scale: { ...item.scale, max: Number(e.target.value) } })}
          />
          <Input
            aria-label="Label of the lowest point"
            className="w-44"
            value={item.scale.minLabel}
            onChange={(e) => onChange({ scale: { ...item.scale, minLabel: e.target.value } })}
          />
          <Input
            aria-label="Label of the highest point"
            className="w-44"
            value={item.scale.maxLabel}
            onChange={(e) => onChange({ scale: { ...item.scale, maxLabel: e.target.value } })}
          />
        </div>
      )}
      {(item.kind === "single" || item.kind === "multiple") && (
        <Input
          aria-label="Options, one per comma"
          value={item.options.join(", ")}
          onChange={(e) =>
            onChange({
              options: e.target.value
                .split(",")
                .map((o) => o.trim())
                .filter(Boolean),
            })
          }
        />
      )}
    </div>
  );
}
