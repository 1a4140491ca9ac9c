"use client";
// On the wizard's trial page: the study's questionnaires for before and after
// the trial, each one click from a one-time link to open on a tablet.
import { useMutation, useQuery } from "@tanstack/react-query";
import { ClipboardList } from "lucide-react";
import { useState } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { ParticipantLink } from "@/ui/participant-link";
import { Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

export function TrialQuestionnaires({
  studyId,
  trialId,
  participantId,
}: {
  studyId: string;
  trialId: string;
  participantId: string;
}) {
  const trpc = useTRPC();
  const list = useQuery(trpc.questionnaires.list.queryOptions({ studyId }));
  const [links, setLinks] = useState<Record<string, string>>({});
  const createLink = useMutation(trpc.questionnaires.createLink.mutationOptions());
  const attached = (list.data ?? []).filter((q) => q.timing !== "none" && q.latestVersion);
  if (!attached.length) return null;
  const open = async (questionnaireId: string) => {
    const link = await createLink.mutateAsync({ questionnaireId, participantId, trialId });
    setLinks((l) => ({ ...l, [questionnaireId]: `${window.location.origin}${link.path}` }));
  };
  return (
    <Card className="space-y-3 p-4 text-sm">
      <h2 className="flex items-center gap-2 font-semibold">
        <ClipboardList className="h-4 w-4" aria-hidden /> Questionnaires
      </h2>
      {attached.map((q) => (
        <div key={q.id} className="space-y-1">
          <div>
            {q.name} <span className="text-xs text-slate-500">({q.timing} the trial)</span>
          </div>
          {links[q.id] ? (
            <ParticipantLink url={links[q.id]!} testId={`questionnaire-link-${q.name}`} />
          ) : (
            <Button size="sm" variant="secondary" disabled={createLink.isPending} onClick={() => void open(q.id)}>
              {/* The questionnaire's name is heard, not shown: the row already shows it. */}
              Open<span className="sr-only"> {q.name}</span> for the participant
            </Button>
          )}
        </div>
      ))}
      <p className="text-xs text-slate-500">
        Each link works once, for this participant only, and expires in two hours.
      </p>
      <Problem error={createLink.error} />
    </Card>
  );
}
