"use client";
// A questionnaire link sent ahead to one participant (a consent form before
// the visit, say): chosen questionnaire, days it stays valid, the link to copy.
import { useMutation, useQuery } from "@tanstack/react-query";
import { useState } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, Input, NativeSelect } from "@/ui/field";
import { ParticipantLink } from "@/ui/participant-link";
import { Problem } from "@/ui/problem";

export function SendLinkDialog({
  studyId,
  participantId,
  code,
}: {
  studyId: string;
  participantId: string;
  code: string;
}) {
  const trpc = useTRPC();
  const [open, setOpen] = useState(false);
  const list = useQuery({ ...trpc.questionnaires.list.queryOptions({ studyId }), enabled: open });
  const published = (list.data ?? []).filter((q) => q.latestVersion);
  const [questionnaireId, setQuestionnaireId] = useState("");
  const [days, setDays] = useState(7);
  const createLink = useMutation(trpc.questionnaires.createLink.mutationOptions());
  const url = createLink.data ? `${window.location.origin}${createLink.data.path}` : null;
  return (
    <Dialog
      title={`A questionnaire link for ${code}`}
      description="The link works once, for this participant only. Send it by your usual channel; the platform sends nothing itself."
      open={open}
      onOpenChange={(o) => (setOpen(o), createLink.reset())}
      trigger={
        <Button size="sm" variant="ghost" aria-label={`Questionnaire link for ${code}`}>
          Link
        </Button>
      }
    >
      <div className="space-y-3">
        <Field
          label="Questionnaire"
          hint={list.data && !published.length ? "Publish a questionnaire first." : undefined}
        >
          {(p) => (
            <NativeSelect {...p} value={questionnaireId} onChange={(e) => setQuestionnaireId(e.target.value)}>
              <option value="">Choose…</option>
              {published.map((q) => (
                <option key={q.id} value={q.id}>
                  {q.name}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <Field label="Valid for (days)">
          {(p) => (
            <Input
              {...p}
              type="number"
              min={1}
              max={30}
              value={days}
              onChange={(e) => setDays(Number(e.target.value))}
            />
          )}
        </Field>
        <Button
          disabled={!questionnaireId || createLink.isPending}
          onClick={() =>
            createLink.mutate({ questionnaireId, participantId, expiresInMinutes: Math.round(days * 24 * 60) })
          }
        >
          Make the link
        </Button>
        <Problem error={createLink.error} />
        {url && <ParticipantLink url={url} testId="sent-link" />}
      </div>
    </Dialog>
  );
}
