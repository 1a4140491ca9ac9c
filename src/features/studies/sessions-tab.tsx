"use client";
// A study's session list: who comes when, in which condition, run by whom.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { useStartSession } from "@/features/sessions/use-start-session";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Badge, Card, EmptyState, STATUS_TONE } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";
import { clockDateTime } from "@/ui/clock-time";

export function SessionsTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const sessions = useQuery(trpc.sessions.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.sessions.list.queryKey({ studyId }) });
  const remove = useMutation(trpc.sessions.remove.mutationOptions({ onSuccess: refresh }));
  const start = useStartSession();
  const manage = studyRoleMay(role, "participant.manage");
  return (
    <div className="space-y-6">
      {manage && <ScheduleSession studyId={studyId} onPlanned={refresh} />}
      <ListView
        query={sessions}
        problem={remove.error ?? start.error}
        empty={
          <EmptyState title="No sessions planned yet.">
            Plan one for each participant once they are assigned to a condition.
          </EmptyState>
        }
        columns={
          <>
            <Th>Planned</Th>
            <Th>Participant</Th>
            <Th>Condition</Th>
            <Th>Wizard</Th>
            <Th>Status</Th>
            <Th className="text-right">Actions</Th>
          </>
        }
        row={(s) => (
          <tr key={s.id}>
            <Td>{clockDateTime(s.plannedAt)}</Td>
            <Td className="font-mono">{s.participantCode}</Td>
            <Td>{s.conditionName ?? <span className="text-slate-500">hidden</span>}</Td>
            <Td>{s.wizardName ?? "—"}</Td>
            <Td>
              {s.trialStatus ? (
                <Badge tone={STATUS_TONE[s.trialStatus]}>{s.trialStatus.replace("_", " ")}</Badge>
              ) : (
                <Badge>planned</Badge>
              )}
            </Td>
            <Td className="space-x-2 text-right">
              {s.mayRun && s.trialStatus !== "completed" && s.trialStatus !== "aborted" && (
                <Button
                  size="sm"
                  aria-label={`${s.trialId ? "Continue" : "Start"} the session of ${s.participantCode}`}
                  disabled={start.isPending}
                  onClick={() => start.mutate({ sessionId: s.id })}
                >
                  {s.trialId ? "Continue" : "Start"}
                </Button>
              )}
              {manage && !s.trialId && (
                <Button
                  size="sm"
                  variant="ghost"
                  aria-label={`Remove the session of ${s.participantCode}`}
                  onClick={() => remove.mutate({ sessionId: s.id })}
                >
                  Remove
                </Button>
              )}
            </Td>
          </tr>
        )}
      />
    </div>
  );
}

/** Local time for a datetime-local field, an hour from now. */
function inAnHour() {
  const local = new Date(Date.now() + 3_600_000 - new Date().getTimezoneOffset() * 60_000);
  return local.toISOString().slice(0, 16);
}

function ScheduleSession({ studyId, onPlanned }: { studyId: string; onPlanned: () => void }) {
  const trpc = useTRPC();
  const participants = useQuery(trpc.participants.list.queryOptions({ studyId }));
  const members = useQuery(trpc.members.list.queryOptions({ studyId }));
  const [participantId, setParticipantId] = useState("");
  const [wizardId, setWizardId] = useState("");
  const [when, setWhen] = useState(inAnHour);
  const schedule = useMutation(trpc.sessions.schedule.mutationOptions({ onSuccess: onPlanned }));
  const assigned = participants.data?.filter((p) => p.conditionId && p.consentStatus !== "withdrawn") ?? [];
  // Wizards first: they run most sessions.
  const wizards = (members.data ?? [])
    .filter((m) => m.role !== "observer")
    .sort((a, b) => Number(b.role === "wizard") - Number(a.role === "wizard"));
  const submit = (e: FormEvent) => {
    e.preventDefault();
    schedule.mutate({ participantId, wizardId: wizardId || wizards[0]!.userId, plannedAt: new Date(when) });
  };
  return (
    <Card className="p-5">
      <h2 className="mb-3 font-semibold">Plan a session</h2>
      <form onSubmit={submit} className="flex flex-wrap items-end gap-3">
        <div className="w-44">
          <Field
            label="Participant"
            required
            hint={assigned.length ? undefined : "Assign participants to conditions first."}
          >
            {(p) => (
              <NativeSelect {...p} value={participantId} onChange={(e) => setParticipantId(e.target.value)}>
                <option value="">Choose…</option>
                {assigned.map((x) => (
                  <option key={x.id} value={x.id}>
                    {x.code}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
        <div className="w-56">
          <Field label="When" required error={fieldError(schedule.error, "plannedAt")}>
            {(p) => <Input {...p} type="datetime-local" value={when} onChange={(e) => setWhen(e.target.value)} />}
          </Field>
        </div>
        <div className="w-56">
          <Field label="Wizard" required>
            {(p) => (
              <NativeSelect
                {...p}
                value={wizardId || wizards[0]?.userId || ""}
                onChange={(e) => setWizardId(e.target.value)}
              >
                {wizards.map((w) => (
                  <option key={w.userId} value={w.userId}>
                    {w.name} ({w.role})
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
        <Button type="submit" className="mb-5" disabled={!participantId || !wizards.length || schedule.isPending}>
          Plan session
        </Button>
      </form>
      <Problem error={schedule.error && !fieldError(schedule.error, "plannedAt") ? schedule.error : null} />
    </Card>
  );
}
