"use client";
import { useQuery } from "@tanstack/react-query";
import Link from "next/link";
import { useState } from "react";
import { studyRoleMay } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Problem } from "@/ui/problem";
import { Badge, ROLE_TONE, Spinner, STATUS_TONE } from "@/ui/surface";
import { Tabs } from "@/ui/tabs";
import { CodingTab } from "../coding/coding-tab";
import { ConditionsTab } from "./conditions-tab";
import { ExperimentsTab } from "./experiments-tab";
import { MembersTab } from "./members-tab";
import { MethodsTab } from "./methods-tab";
import { OverviewTab } from "./overview-tab";
import { ParticipantsTab } from "./participants-tab";
import { QuestionnairesTab } from "./questionnaires-tab";
import { ResultsTab } from "./results-tab";
import { SessionsTab } from "./sessions-tab";
import { SoundsTab } from "./sounds-tab";
import { TrialsTab } from "./trials-tab";

export function StudyPage({ studyId }: { studyId: string }) {
  const trpc = useTRPC();
  const study = useQuery(trpc.studies.get.queryOptions({ studyId }));
  const [tab, setTab] = useState("overview");
  if (study.isPending) return <Spinner />;
  if (study.error?.data?.code === "NOT_FOUND") return <StudyNotFound />;
  if (study.error) return <Problem error={study.error} />;
  const s = study.data;
  const role = s.myRole;
  // A blinded wizard gets no tab that would name a condition; the server refuses them anyway.
  const blinded = role === "wizard" && s.settings.blinding.conditionsFromWizards;
  return (
    <div>
      <div className="mb-6">
        <Link href="/studies" className="text-sm text-slate-500 hover:text-slate-800">
          ← My studies
        </Link>
        <div className="mt-2 flex flex-wrap items-center gap-3">
          <h1 className="text-2xl font-semibold">{s.title}</h1>
          <Badge tone={STATUS_TONE[s.status]}>{s.status}</Badge>
          <span className="text-sm text-slate-500">
            You are <Badge tone={ROLE_TONE[role]}>{role}</Badge>
          </span>
        </div>
      </div>
      <Tabs
        label="Study sections"
        value={tab}
        onValueChange={setTab}
        tabs={[
          { id: "overview", label: "Overview", content: <OverviewTab study={s} /> },
          { id: "members", label: "Members", content: <MembersTab studyId={studyId} role={role} /> },
          ...(blinded
            ? []
            : [
                { id: "experiments", label: "Experiments", content: <ExperimentsTab studyId={studyId} role={role} /> },
                { id: "sounds", label: "Sounds", content: <SoundsTab studyId={studyId} role={role} /> },
                {
                  id: "conditions",
                  label: "Conditions",
                  content: <ConditionsTab studyId={studyId} role={role} settings={s.settings} />,
                },
              ]),
          {
            id: "participants",
            label: "Participants",
            content: <ParticipantsTab studyId={studyId} role={role} settings={s.settings} blinded={blinded} />,
          },
          { id: "sessions", label: "Sessions", content: <SessionsTab studyId={studyId} role={role} /> },
          {
            id: "questionnaires",
            label: "Questionnaires",
            content: <QuestionnairesTab studyId={studyId} role={role} />,
          },
          { id: "coding", label: "Coding", content: <CodingTab studyId={studyId} role={role} /> },
          ...(studyRoleMay(role, "data.read")
            ? [
                { id: "results", label: "Results", content: <ResultsTab studyId={studyId} role={role} /> },
                { id: "methods", label: "Methods", content: <MethodsTab studyId={studyId} /> },
              ]
            : []),
          {
            id: "trials",
            label: "Trials",
            content: <TrialsTab studyId={studyId} role={role} blinded={blinded} studyStatus={s.status} />,
          },
        ]}
      />
    </div>
  );
}

function StudyNotFound() {
  return (
    <div className="py-16 text-center">
      <h1 className="text-2xl font-semibold">Study not found</h1>
      <p className="mt-2 text-slate-600">It does not exist, or you are not a member of it.</p>
      <Link href="/studies" className="mt-4 inline-block text-brand-600 hover:underline">
        Back to my studies
      </Link>
    </div>
  );
}
