"use client";
import { useQuery } from "@tanstack/react-query";
import Link from "next/link";
import { SYSTEM_OPERATIONS, type SystemRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Problem } from "@/ui/problem";
import { Badge, Card, EmptyState, ROLE_TONE, Spinner, STATUS_TONE } from "@/ui/surface";
import { LiveNow } from "./live-now";
import { NewStudyDialog } from "./new-study-dialog";
import { StudyFromTemplateDialog } from "./study-from-template-dialog";

export function StudyList({ systemRole }: { systemRole: SystemRole }) {
  const trpc = useTRPC();
  const studies = useQuery(trpc.studies.mine.queryOptions());
  const canCreate = (SYSTEM_OPERATIONS["study.create"] as readonly SystemRole[]).includes(systemRole);
  return (
    <section>
      <LiveNow />
      <div className="mb-6 flex items-center justify-between">
        <h1 className="text-2xl font-semibold">My studies</h1>
        {canCreate && (
          <div className="flex gap-2">
            {studies.data && studies.data.length > 0 && <StudyFromTemplateDialog />}
            <NewStudyDialog />
          </div>
        )}
      </div>
      {studies.isPending && <Spinner />}
      <Problem error={studies.error} />
      {studies.data?.length === 0 && (
        <EmptyState title="You are not part of any study yet.">
          {canCreate ? "Create one with “New study”." : "A study's owner can add you as a member."}
        </EmptyState>
      )}
      <ul className="grid gap-4 sm:grid-cols-2 lg:grid-cols-3">
        {studies.data?.map((s) => (
          <li key={s.id}>
            <Link
              href={`/studies/${s.id}`}
              className="block focus:outline-none focus-visible:ring-2 focus-visible:ring-brand-500 rounded-lg"
            >
              <Card className="h-full p-5 hover:border-brand-500">
                <div className="flex items-start justify-between gap-2">
                  <h2 className="font-semibold">{s.title}</h2>
                  <Badge tone={STATUS_TONE[s.status]}>{s.status}</Badge>
                </div>
                <p className="mt-2 line-clamp-2 text-sm text-slate-600">{s.description || "No description."}</p>
                <div className="mt-4 flex items-center gap-3 text-xs text-slate-500">
                  <Badge tone={ROLE_TONE[s.role]}>{s.role}</Badge>
                  <span>{s.experimentCount} experiments</span>
                  <span>{s.participantCount} participants</span>
                  <span>{s.trialCount} trials</span>
                </div>
              </Card>
            </Link>
          </li>
        ))}
      </ul>
    </section>
  );
}
