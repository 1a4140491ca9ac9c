"use client";
// A study's questionnaires: the standard instruments in one click, custom ones
// built and versioned, each attached before or after the trial (or not).
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import Link from "next/link";
import { useRouter } from "next/navigation";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { NativeSelect } from "@/ui/field";
import { Badge, EmptyState } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";

const TIMING = { before: "Before the trial", after: "After the trial", none: "Not attached (links by hand)" } as const;

export function QuestionnairesTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const router = useRouter();
  const queryClient = useQueryClient();
  const list = useQuery(trpc.questionnaires.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.questionnaires.list.queryKey({ studyId }) });
  const create = useMutation(trpc.questionnaires.create.mutationOptions({ onSuccess: refresh }));
  const save = useMutation(trpc.questionnaires.save.mutationOptions({ onSuccess: refresh }));
  const publish = useMutation(trpc.questionnaires.publish.mutationOptions({ onSuccess: refresh }));
  const edit = studyRoleMay(role, "experiment.edit");
  return (
    <div className="space-y-4">
      {edit && (
        <div className="flex flex-wrap gap-2">
          <Button onClick={() => create.mutate({ studyId, instrument: "sus" })}>Add the System Usability Scale</Button>
          <Button variant="secondary" onClick={() => create.mutate({ studyId, instrument: "godspeed" })}>
            Add Godspeed
          </Button>
          <Button
            variant="secondary"
            onClick={async () =>
              router.push(`/questionnaires/${(await create.mutateAsync({ studyId, name: "New questionnaire" })).id}`)
            }
          >
            Build a questionnaire
          </Button>
        </div>
      )}
      <ListView
        query={list}
        problem={create.error ?? save.error ?? publish.error}
        empty={
          <EmptyState title="No questionnaires yet.">
            Add a standard scale, or build your own with a consent form, Likert items and open questions.
          </EmptyState>
        }
        columns={
          <>
            <Th>Questionnaire</Th>
            <Th>When</Th>
            <Th>Published</Th>
            <Th className="text-right">Actions</Th>
          </>
        }
        row={(q) => (
          <tr key={q.id}>
            <Td>
              <div className="font-medium">{q.name}</div>
              {q.instrument && <div className="text-xs text-slate-500">standard instrument, scored as published</div>}
            </Td>
            <Td>
              {edit ? (
                <NativeSelect
                  aria-label={`When ${q.name} is filled in`}
                  className="w-64"
                  value={q.timing}
                  onChange={(e) =>
                    save.mutate({ questionnaireId: q.id, timing: e.target.value as keyof typeof TIMING })
                  }
                >
                  {Object.entries(TIMING).map(([value, label]) => (
                    <option key={value} value={value}>
                      {label}
                    </option>
                  ))}
                </NativeSelect>
              ) : (
                TIMING[q.timing]
              )}
            </Td>
            <Td>
              {q.latestVersion ? <Badge tone="green">version {q.latestVersion}</Badge> : <Badge>draft only</Badge>}
            </Td>
            <Td className="space-x-2 text-right">
              <Button variant="ghost" size="sm" asChild>
                <Link href={`/questionnaires/${q.id}`}>{edit ? "Edit" : "Open"}</Link>
              </Button>
              {studyRoleMay(role, "version.publish") && (
                <Button
                  variant="secondary"
                  size="sm"
                  aria-label={`Publish ${q.name}`}
                  disabled={publish.isPending}
                  onClick={() => publish.mutate({ questionnaireId: q.id })}
                >
                  Publish
                </Button>
              )}
            </Td>
          </tr>
        )}
      />
    </div>
  );
}
