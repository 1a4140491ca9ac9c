"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import type { DemographicField, StudySettings } from "@/core/studies/settings";
import { SendLinkDialog } from "@/features/questionnaires/send-link-dialog";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Badge, Card, EmptyState, STATUS_TONE } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";

const CONSENT = ["pending", "given", "declined", "withdrawn"] as const;
type Consent = (typeof CONSENT)[number];

export function ParticipantsTab({
  studyId,
  role,
  settings,
  blinded,
}: {
  studyId: string;
  role: StudyRole;
  settings: StudySettings;
  blinded: boolean;
}) {
  const strategy = settings.assignment.strategy;
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const participants = useQuery(trpc.participants.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.participants.list.queryKey({ studyId }) });
  const update = useMutation(trpc.participants.update.mutationOptions({ onSuccess: refresh }));
  const conditions = useQuery({ ...trpc.conditions.list.queryOptions({ studyId }), enabled: !blinded });
  const assign = useMutation(trpc.conditions.assign.mutationOptions({ onSuccess: refresh }));
  const reinstate = useMutation(trpc.participants.reinstate.mutationOptions({ onSuccess: refresh }));
  const askToReinstate = (participantId: string, code: string) => {
    const reason = window.prompt(
      `Why is ${code} reinstated? Their consent is recorded as given again, and your reason goes into the study's audit log.`,
    );
    if (reason?.trim()) reinstate.mutate({ participantId, reason: reason.trim() });
  };
  const conditionName = (id: string | null) => conditions.data?.find((c) => c.id === id)?.name;
  const manage = studyRoleMay(role, "participant.manage");
  return (
    <div className="space-y-6">
      {manage && <AddParticipant studyId={studyId} fields={settings.demographics} onAdded={refresh} />}
      <ListView
        query={participants}
        problem={update.error ?? assign.error ?? reinstate.error}
        empty={<EmptyState title="No participants yet." />}
        columns={
          <>
            <Th>Code</Th>
            <Th>Consent</Th>
            <Th>Consent date</Th>
            <Th>Document</Th>
            {settings.demographics.length > 0 && <Th>Demographics</Th>}
            <Th>Condition</Th>
            <Th>Trials</Th>
            {manage && <Th className="text-right">Questionnaire</Th>}
          </>
        }
        row={(p) => (
          <tr key={p.id}>
            <Td className="font-mono">{p.code}</Td>
            <Td>
              {manage && p.consentStatus !== "withdrawn" ? (
                <NativeSelect
                  aria-label={`Consent of ${p.code}`}
                  className="w-36"
                  value={p.consentStatus}
                  onChange={(e) => {
                    const consentStatus = e.target.value as Consent;
                    update.mutate({
                      participantId: p.id,
                      consentStatus,
                      consentDate: consentStatus === "given" ? new Date() : p.consentDate,
                    });
                  }}
                >
                  {CONSENT.map((c) => (
                    <option key={c}>{c}</option>
                  ))}
                </NativeSelect>
              ) : (
                <Badge tone={STATUS_TONE[p.consentStatus]}>{p.consentStatus}</Badge>
              )}
              {p.consentStatus === "withdrawn" && studyRoleMay(role, "participant.reinstate") && (
                <Button variant="ghost" className="ml-2" onClick={() => askToReinstate(p.id, p.code)}>
                  Reinstate…
                </Button>
              )}
            </Td>
            <Td>
              {p.consentDate ? new Date(p.consentDate).toLocaleDateString() : "—"}
              {p.consentStatus === "withdrawn" && (
                <div className="text-xs text-red-700">data excluded from analysis and exports</div>
              )}
            </Td>
            <Td className="text-xs">{p.consentVersion ?? "—"}</Td>
            {settings.demographics.length > 0 && (
              <Td className="text-xs text-slate-600">
                {settings.demographics
                  .filter((f) => (p.demographics as Record<string, unknown>)[f.key] !== undefined)
                  .map((f) => `${f.label}: ${String((p.demographics as Record<string, unknown>)[f.key])}`)
                  .join(" · ") || "—"}
              </Td>
            )}
            <Td>
              {blinded ? (
                <span className="text-slate-500">hidden</span>
              ) : p.conditionId ? (
                <>
                  {conditionName(p.conditionId)}
                  {p.stratum !== null && <div className="text-xs text-slate-500">stratum: {p.stratum}</div>}
                </>
              ) : manage && conditions.data?.length && strategy === "fixed" ? (
                <NativeSelect
                  aria-label={`Condition of ${p.code}`}
                  className="w-48"
                  value=""
                  onChange={(e) => assign.mutate({ participantId: p.id, conditionId: e.target.value })}
                >
                  <option value="">Choose…</option>
                  {conditions.data.map((c) => (
                    <option key={c.id} value={c.id}>
                      {c.name}
                    </option>
                  ))}
                </NativeSelect>
              ) : manage && conditions.data?.length ? (
                <Button
                  size="sm"
                  variant="secondary"
                  aria-label={`Assign ${p.code}`}
                  onClick={() => assign.mutate({ participantId: p.id })}
                >
                  Assign ({strategy})
                </Button>
              ) : (
                "—"
              )}
            </Td>
            <Td>{p.trialCount}</Td>
            {manage && (
              <Td className="text-right">
                <SendLinkDialog studyId={studyId} participantId={p.id} code={p.code} />
              </Td>
            )}
          </tr>
        )}
      />
    </div>
  );
}

function AddParticipant({
  studyId,
  fields,
  onAdded,
}: {
  studyId: string;
  fields: DemographicField[];
  onAdded: () => void;
}) {
  const trpc = useTRPC();
  const [code, setCode] = useState("");
  const [answers, setAnswers] = useState<Record<string, string>>({});
  const [consent, setConsent] = useState<Consent>("pending");
  const create = useMutation(
    trpc.participants.create.mutationOptions({
      onSuccess: () => {
        setCode("");
        setAnswers({});
        onAdded();
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    // Unanswered questions stay out: every answer is optional.
    const demographics = Object.fromEntries(
      fields
        .filter((f) => answers[f.key]?.trim())
        .map((f) => [f.key, f.type === "number" ? Number(answers[f.key]) : answers[f.key]!.trim()]),
    );
    create.mutate({
      studyId,
      code,
      consentStatus: consent,
      consentDate: consent === "given" ? new Date() : null,
      demographics,
    });
  };
  return (
    <Card className="p-5">
      <h2 className="mb-3 font-semibold">Add a participant</h2>
      <form onSubmit={submit} className="flex flex-wrap items-end gap-3">
        <div className="w-56">
          <Field
            label="Participant code"
            required
            error={fieldError(create.error, "code")}
            hint="A code, never a name."
          >
            {(p) => <Input {...p} value={code} onChange={(e) => setCode(e.target.value)} placeholder="P004" />}
          </Field>
        </div>
        <div className="w-44">
          <Field label="Consent">
            {(p) => (
              <NativeSelect {...p} value={consent} onChange={(e) => setConsent(e.target.value as Consent)}>
                {CONSENT.map((c) => (
                  <option key={c}>{c}</option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
        {fields.map((f) => (
          <div key={f.key} className="w-40">
            <Field label={f.label} hint="optional">
              {(p) =>
                f.type === "choice" ? (
                  <NativeSelect
                    {...p}
                    value={answers[f.key] ?? ""}
                    onChange={(e) => setAnswers({ ...answers, [f.key]: e.target.value })}
                  >
                    <option value="">—</option>
                    {f.options.map((o) => (
                      <option key={o}>{o}</option>
                    ))}
                  </NativeSelect>
                ) : (
                  <Input
                    {...p}
                    type={f.type === "number" ? "number" : "text"}
                    value={answers[f.key] ?? ""}
                    onChange={(e) => setAnswers({ ...answers, [f.key]: e.target.value })}
                  />
                )
              }
            </Field>
          </div>
        ))}
        <Button type="submit" disabled={create.isPending} className="mb-5">
          Add participant
        </Button>
      </form>
      {create.error && !fieldError(create.error, "code") && <Problem error={create.error} />}
    </Card>
  );
}
