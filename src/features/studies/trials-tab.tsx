"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import Link from "next/link";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { type StudyStatus, trialRefusal } from "@/core/studies/status";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { DownloadLink } from "@/ui/download-link";
import { Field, NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Badge, Card, EmptyState, STATUS_TONE } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";
import { WizardChoice, wizardIdOf, type WizardChoiceValue } from "./wizard-choice";
import { clockDateTime } from "@/ui/clock-time";

export function TrialsTab({
  studyId,
  role,
  blinded,
  studyStatus,
}: {
  studyId: string;
  role: StudyRole;
  blinded: boolean;
  studyStatus: StudyStatus;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const trials = useQuery(trpc.trials.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.trials.list.queryKey({ studyId }) });
  return (
    <div className="space-y-6">
      {/* A blinded wizard starts trials from their sessions: choosing an experiment would reveal the condition. */}
      {studyRoleMay(role, "trial.create") && !blinded && (
        <NewTrial studyId={studyId} refusal={trialRefusal(studyStatus)} onCreated={refresh} />
      )}
      {studyRoleMay(role, "data.read") && (
        <DownloadLink href={`/api/studies/${studyId}/export`}>
          Download the whole study (zip: design and its methods text, every trial's record, events and ELAN file,
          questionnaire answers)
        </DownloadLink>
      )}
      <ListView
        query={trials}
        empty={<EmptyState title="No trials yet." />}
        columns={
          <>
            <Th>Participant</Th>
            <Th>Experiment</Th>
            <Th>Wizard</Th>
            <Th>Scores</Th>
            <Th>Status</Th>
            <Th>Created</Th>
            <Th className="text-right">Open</Th>
          </>
        }
        row={(t) => (
          <tr key={t.id}>
            <Td className="font-mono">{t.participantCode ?? "—"}</Td>
            <Td>
              {t.experimentName}{" "}
              {t.isRehearsal ? (
                <Badge tone="amber">rehearsal</Badge>
              ) : (
                t.version !== null && <span className="text-xs text-slate-500">v{t.version}</span>
              )}
              {t.participantWithdrawn && <div className="text-xs text-red-700">withdrawn: excluded from analysis</div>}
            </Td>
            {/* No wizard yet: the first of the study's wizards to start it runs it. */}
            <Td>{t.wizardId === null ? <span className="text-slate-500">any wizard</span> : (t.wizardName ?? "—")}</Td>
            <Td className="text-xs">
              {t.scores
                .map((s) => `${s.name}: ${Number.isInteger(s.score) ? s.score : s.score.toFixed(2)}`)
                .join(" · ") || "—"}
            </Td>
            <Td>
              <Badge tone={STATUS_TONE[t.status]}>{t.status.replace("_", " ")}</Badge>
            </Td>
            <Td>{clockDateTime(t.createdAt)}</Td>
            <Td className="text-right">
              <Link
                className="font-medium text-brand-600 hover:underline"
                href={`/trials/${t.id}`}
                aria-label={`${studyRoleMay(role, "trial.run") ? "Run" : "Watch"} trial of ${t.participantCode ?? "no participant"}`}
              >
                {studyRoleMay(role, "trial.run") ? "Run" : "Watch"}
              </Link>
              {(t.status === "completed" || t.status === "aborted") &&
                !t.participantWithdrawn &&
                studyRoleMay(role, "data.read") && (
                  <Link
                    className="ml-3 font-medium text-brand-600 hover:underline"
                    href={`/trials/${t.id}/analysis`}
                    aria-label={`Analysis of the trial of ${t.participantCode ?? "no participant"}`}
                  >
                    Analysis
                  </Link>
                )}
            </Td>
          </tr>
        )}
      />
    </div>
  );
}

/** Trials run only published versions, for a participant of this study. */
function NewTrial({
  studyId,
  refusal,
  onCreated,
}: {
  studyId: string;
  /** Why this study runs no trials now (its status), shown instead of letting the form be sent. */
  refusal: string | null;
  onCreated: () => void;
}) {
  const trpc = useTRPC();
  const experiments = useQuery(trpc.experiments.list.queryOptions({ studyId }));
  const participants = useQuery(trpc.participants.list.queryOptions({ studyId }));
  const [experimentId, setExperimentId] = useState("");
  const [participantId, setParticipantId] = useState("");
  // Unassigned by default: whoever starts the trial is recorded as its wizard, so it is credited to who ran it.
  const [wizard, setWizard] = useState<WizardChoiceValue>("any");
  const versions = useQuery({ ...trpc.versions.list.queryOptions({ experimentId }), enabled: Boolean(experimentId) });
  const create = useMutation(trpc.trials.create.mutationOptions({ onSuccess: onCreated }));
  const latest = versions.data?.[0];
  const submit = (e: FormEvent) => {
    e.preventDefault();
    if (latest)
      create.mutate({ versionId: latest.id, participantId: participantId || null, wizardId: wizardIdOf(wizard) });
  };
  return (
    <Card className="p-5">
      <h2 className="mb-3 font-semibold">New trial</h2>
      <form onSubmit={submit} className="flex flex-wrap items-end gap-3">
        <div className="w-64">
          <Field
            label="Experiment"
            required
            hint={
              experimentId && !latest && !versions.isPending
                ? "Publish this experiment first."
                : latest
                  ? `Runs published version ${latest.version}.`
                  : undefined
            }
          >
            {(p) => (
              <NativeSelect {...p} value={experimentId} onChange={(e) => setExperimentId(e.target.value)}>
                <option value="">Choose…</option>
                {experiments.data?.map((x) => (
                  <option key={x.id} value={x.id}>
                    {x.name}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
        <div className="w-48">
          <Field label="Participant" required>
            {(p) => (
              <NativeSelect {...p} value={participantId} onChange={(e) => setParticipantId(e.target.value)}>
                <option value="">Choose…</option>
                {participants.data?.map((x) => (
                  <option key={x.id} value={x.id}>
                    {x.code}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
        <div className="w-64">
          <WizardChoice studyId={studyId} value={wizard} onChange={setWizard} />
        </div>
        <Button type="submit" disabled={!latest || !participantId || create.isPending || !!refusal} className="mb-5">
          Create trial
        </Button>
      </form>
      {refusal && <p className="text-sm text-amber-800">{refusal}</p>}
      <Problem error={create.error} />
    </Card>
  );
}
