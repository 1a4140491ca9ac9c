"use client";
// One coding scheme's sets and codes: editable by the study's owner and
// researchers, read by everyone else. Saved whole; the server names every
// problem ("sets.0.codes.1.key: "t" is already the key of Technical").
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useEffect, useState } from "react";
import type { Code, Scheme } from "@/core/coding/scheme";
import { newCode } from "@/core/coding/templates";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Input, NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Card, Spinner } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";

export function SchemeEditor({ schemeId, editable }: { schemeId: string; editable: boolean }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const loaded = useQuery(trpc.coding.scheme.queryOptions({ codingSchemeId: schemeId }));
  const [draft, setDraft] = useState<Scheme | null>(null);
  useEffect(() => setDraft(loaded.data?.draft ?? null), [loaded.data]);
  const save = useMutation(
    trpc.coding.saveScheme.mutationOptions({ onSuccess: () => queryClient.invalidateQueries() }),
  );
  if (loaded.isPending || !draft) return <Spinner label="Loading the coding scheme…" />;
  if (loaded.error) return <Problem error={loaded.error} />;
  const setCode = (si: number, ci: number, change: Partial<Code> | null) =>
    setDraft({
      ...draft,
      sets: draft.sets.map((s, i) =>
        i !== si
          ? s
          : {
              ...s,
              codes:
                change === null
                  ? s.codes.filter((_, j) => j !== ci)
                  : s.codes.map((c, j) => (j === ci ? { ...c, ...change } : c)),
            },
      ),
    });
  return (
    <Card className="space-y-4 p-4">
      {editable ? (
        // Exports and the methods text name the scheme by this: a team renames it from "New coding scheme".
        <Input
          aria-label="Scheme name"
          value={draft.name}
          className="w-80 text-lg font-semibold"
          onChange={(e) => setDraft({ ...draft, name: e.target.value })}
        />
      ) : (
        <h3 className="text-lg font-semibold">{draft.name}</h3>
      )}
      {draft.description && <p className="text-sm text-slate-600">{draft.description}</p>}
      {draft.sets.map((set, si) => (
        <section key={si} aria-label={`Set ${set.name}`} className="space-y-2">
          {editable ? (
            <Input
              aria-label="Set name"
              value={set.name}
              className="w-64 font-medium"
              onChange={(e) =>
                setDraft({ ...draft, sets: draft.sets.map((s, i) => (i === si ? { ...s, name: e.target.value } : s)) })
              }
            />
          ) : (
            <h4 className="font-medium">{set.name}</h4>
          )}
          <p className="text-xs text-slate-500">One code of this set at a time: they exclude one another.</p>
          <Table aria-label={`Codes of ${set.name}`}>
            <thead>
              <tr>
                <Th>Code</Th>
                <Th>Key</Th>
                <Th>Colour</Th>
                <Th>Kind</Th>
                <Th>Modifiers</Th>
                {editable && <Th className="text-right">Actions</Th>}
              </tr>
            </thead>
            <tbody>
              {set.codes.map((code, ci) => (
                <tr key={ci}>
                  {editable ? (
                    <>
                      <Td>
                        <Input
                          aria-label="Code name"
                          value={code.name}
                          onChange={(e) => setCode(si, ci, { name: e.target.value })}
                        />
                      </Td>
                      <Td>
                        <Input
                          aria-label={`Key of ${code.name}`}
                          value={code.key}
                          maxLength={1}
                          className="w-14 text-center font-mono"
                          onChange={(e) => setCode(si, ci, { key: e.target.value.toLowerCase() })}
                        />
                      </Td>
                      <Td>
                        <Input
                          type="color"
                          aria-label={`Colour of ${code.name}`}
                          value={code.colour}
                          className="w-16 p-1"
                          onChange={(e) => setCode(si, ci, { colour: e.target.value })}
                        />
                      </Td>
                      <Td>
                        <NativeSelect
                          aria-label={`Kind of ${code.name}`}
                          value={code.kind}
                          onChange={(e) => setCode(si, ci, { kind: e.target.value as Code["kind"] })}
                        >
                          <option value="point">Point event</option>
                          <option value="state">State (start and end)</option>
                        </NativeSelect>
                      </Td>
                      <Td>
                        <Input
                          aria-label={`Modifiers of ${code.name}, separated by commas`}
                          value={code.modifiers.join(", ")}
                          onChange={(e) =>
                            setCode(si, ci, {
                              modifiers: e.target.value
                                .split(",")
                                .map((m) => m.trim())
                                .filter(Boolean),
                            })
                          }
                        />
                      </Td>
                      <Td className="text-right">
                        <Button variant="ghost" size="sm" onClick={() => setCode(si, ci, null)}>
                          Remove
                        </Button>
                      </Td>
                    </>
                  ) : (
                    <>
                      <Td>
                        <span className="mr-2 inline-block h-3 w-3 rounded-full" style={{ background: code.colour }} />
                        {code.name}
                      </Td>
                      <Td>
                        <kbd className="rounded border border-slate-300 px-1.5 font-mono">{code.key}</kbd>
                      </Td>
                      <Td>{code.colour}</Td>
                      <Td>{code.kind === "point" ? "Point event" : "State"}</Td>
                      <Td>{code.modifiers.join(", ") || "—"}</Td>
                    </>
                  )}
                </tr>
              ))}
            </tbody>
          </Table>
          {editable && (
            <Button
              variant="secondary"
              size="sm"
              onClick={() =>
                setDraft({
                  ...draft,
                  sets: draft.sets.map((s, i) => (i === si ? { ...s, codes: [...s.codes, newCode(draft)] } : s)),
                })
              }
            >
              Add a code to {set.name}
            </Button>
          )}
        </section>
      ))}
      {editable && (
        <div className="flex gap-2">
          <Button
            variant="secondary"
            onClick={() => {
              const n = draft.sets.length + 1;
              setDraft({
                ...draft,
                sets: [...draft.sets, { id: `set-${n}`, name: `Set ${n}`, codes: [newCode(draft)] }],
              });
            }}
          >
            Add a set
          </Button>
          <Button
            disabled={save.isPending}
            onClick={() => save.mutate({ codingSchemeId: schemeId, definition: draft })}
          >
            Save the scheme
          </Button>
        </div>
      )}
      {save.isSuccess && <p className="text-sm text-green-700">Saved. Publish it for observers to code with it.</p>}
      <Problem error={save.error} />
    </Card>
  );
}
