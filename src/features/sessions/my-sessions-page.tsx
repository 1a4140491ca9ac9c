"use client";
// The wizard's "My sessions": what I run next, soonest first, each one click
// from its live trial. Under a blind, the condition is simply not there.
import { useQuery } from "@tanstack/react-query";
import { CalendarClock, Play } from "lucide-react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Problem } from "@/ui/problem";
import { Badge, Card, EmptyState, Spinner, STATUS_TONE } from "@/ui/surface";
import { useStartSession } from "./use-start-session";
import { clockDateTime } from "@/ui/clock-time";

export function MySessionsPage() {
  const trpc = useTRPC();
  const sessions = useQuery(trpc.sessions.mine.queryOptions(undefined, { refetchInterval: 30_000 }));
  const start = useStartSession();
  return (
    <div className="space-y-4">
      <h1 className="text-2xl font-semibold">My sessions</h1>
      <p className="text-sm text-slate-600">The sessions you run that are not finished yet, soonest first.</p>
      {sessions.isPending && <Spinner />}
      <Problem error={sessions.error ?? start.error} />
      {sessions.data?.length === 0 && (
        <EmptyState title="No sessions are planned for you.">
          A researcher plans sessions in a study's Sessions tab.
        </EmptyState>
      )}
      <ul className="space-y-3" aria-label="My sessions">
        {sessions.data?.map((s, i) => (
          <li key={s.id}>
            <Card className={`flex flex-wrap items-center gap-4 p-4 ${i === 0 ? "border-brand-300" : ""}`}>
              <CalendarClock className="h-5 w-5 text-slate-400" aria-hidden />
              <div className="min-w-0 flex-1">
                <div className="font-medium">
                  Participant <span className="font-mono">{s.participantCode}</span>
                  {s.conditionName && <span className="ml-2 text-sm text-slate-500">· {s.conditionName}</span>}
                </div>
                <div className="text-sm text-slate-500">
                  {clockDateTime(s.plannedAt)} · {s.studyTitle}
                </div>
              </div>
              {s.trialStatus && <Badge tone={STATUS_TONE[s.trialStatus]}>{s.trialStatus.replace("_", " ")}</Badge>}
              <Button disabled={start.isPending} onClick={() => start.mutate({ sessionId: s.id })}>
                <Play className="h-4 w-4" aria-hidden /> {s.trialId ? "Continue" : "Start"}
                <span className="sr-only"> the session of {s.participantCode}</span>
              </Button>
            </Card>
          </li>
        ))}
      </ul>
    </div>
  );
}
