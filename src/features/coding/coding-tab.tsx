"use client";
// A study's coding schemes: started from a template or blank, edited by the
// owner and researchers, published as numbered versions observers code with.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { ListView } from "@/ui/list-view";
import { Badge, EmptyState } from "@/ui/surface";
import { Td, Th } from "@/ui/table";
import { SchemeEditor } from "./scheme-editor";

export function CodingTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const list = useQuery(trpc.coding.schemes.queryOptions({ studyId }));
  const [open, setOpen] = useState<string | null>(null);
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.coding.schemes.queryKey({ studyId }) });
  const create = useMutation(
    trpc.coding.createScheme.mutationOptions({
      onSuccess: (s) => {
        setOpen(s.id);
        return refresh();
      },
    }),
  );
  const publish = useMutation(trpc.coding.publishScheme.mutationOptions({ onSuccess: refresh }));
  const edit = studyRoleMay(role, "experiment.edit");
  return (
    <div className="space-y-4">
      {edit && (
        <div className="flex flex-wrap gap-2">
          <Button onClick={() => create.mutate({ studyId, template: "wizard-interventions" })}>
            Add wizard interventions
          </Button>
          <Button variant="secondary" onClick={() => create.mutate({ studyId, template: "participant-engagement" })}>
            Add participant engagement
          </Button>
          <Button variant="secondary" onClick={() => create.mutate({ studyId, name: "New coding scheme" })}>
            Build a coding scheme
          </Button>
        </div>
      )}
      <ListView
        query={list}
        problem={create.error ?? publish.error}
        label="Coding schemes"
        empty={
          <EmptyState title="No coding schemes yet.">
            A coding scheme lets observers mark behaviour with one key per code while a trial runs, and the Results tab
            compare two observers.
          </EmptyState>
        }
        columns={
          <>
            <Th>Coding scheme</Th>
            <Th>Published</Th>
            <Th className="text-right">Actions</Th>
          </>
        }
        row={(s) => (
          <tr key={s.id}>
            <Td className="font-medium">{s.name}</Td>
            <Td>
              {s.latestVersion ? <Badge tone="green">version {s.latestVersion}</Badge> : <Badge>draft only</Badge>}
            </Td>
            <Td className="space-x-2 text-right">
              <Button variant="ghost" size="sm" onClick={() => setOpen(open === s.id ? null : s.id)}>
                {open === s.id ? "Close" : edit ? "Edit" : "Open"}
              </Button>
              {studyRoleMay(role, "version.publish") && (
                <Button
                  variant="secondary"
                  size="sm"
                  aria-label={`Publish ${s.name}`}
                  disabled={publish.isPending}
                  onClick={() => publish.mutate({ codingSchemeId: s.id })}
                >
                  Publish
                </Button>
              )}
            </Td>
          </tr>
        )}
      />
      {open && <SchemeEditor key={open} schemeId={open} editable={edit} />}
    </div>
  );
}
