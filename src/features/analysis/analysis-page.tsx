"use client";
// A trial after the fact: planned against executed, the event timeline with
// deviations and annotations, and the robot's logged joint angles.
import { useQuery } from "@tanstack/react-query";
import Link from "next/link";
import { useMemo, useState } from "react";
import { answerOf } from "@/core/analysis/answers";
import { fidelityReport } from "@/core/analysis/fidelity";
import { moveWords, stepVisits } from "@/core/analysis/moves";
import { trialNames } from "@/core/analysis/names";
import type { TrialProtocol } from "@/core/trial";
import { useTRPC } from "@/lib/trpc";
import { clockDateTime, clockTime } from "@/ui/clock-time";
import { QuestionnaireAnswers } from "./questionnaire-answers";
import { AgreementPanel } from "../coding/agreement-panel";
import { CodeTiers } from "../coding/code-tiers";
import { AnnotationsEditor } from "./annotations-editor";
import { TimelineChart } from "./timeline-chart";
import { EventList, type TimelineItem } from "./event-list";
import { PlannedTable } from "./planned-table";
import { StepPath } from "./step-path";
import { LoopIterations } from "./loop-iterations";
import { recordingGaps } from "@/core/media/recording-parts";
import { RecordingPlayer, useTrialRecording } from "./recording-player";
import { Problem } from "@/ui/problem";
import { Badge, Card, Spinner } from "@/ui/surface";
import { JointAngles } from "./joint-angles";
import { ReplayControl } from "./replay-control";
import { TrialPeople } from "@/features/execution/trial-people";
import { fetchTrialLog } from "./trial-log";

export function AnalysisPage({ trialId }: { trialId: string }) {
  const trpc = useTRPC();
  const trial = useQuery(trpc.trials.get.queryOptions({ trialId }));
  const events = useQuery({ queryKey: ["trial-log", trialId], queryFn: () => fetchTrialLog(trialId) });
  const annotations = useQuery(trpc.trials.annotations.queryOptions({ trialId }));
  const recording = useTrialRecording(trialId, trial.data?.myRole !== "wizard");
  const [playheadMs, setPlayheadMs] = useState<number | null>(null);
  const samples = useQuery({
    ...trpc.trials.samples.queryOptions({ trialId, topic: "/joint_states", maxPoints: 2000 }),
    enabled: trial.data?.myRole !== "wizard",
  });
  const report = useMemo(
    () =>
      trial.data && events.data
        ? fidelityReport(trial.data.protocol as TrialProtocol, events.data, trial.data.actionNames)
        : null,
    [trial.data, events.data],
  );
  const named = useMemo(
    () =>
      trial.data && events.data
        ? trialNames(trial.data.protocol as TrialProtocol, events.data, trial.data.actionNames)
        : null,
    [trial.data, events.data],
  );
  const visits = useMemo(() => stepVisits(events.data ?? []), [events.data]);
  // Every event and annotation in time order, and the deviations: built once per load, not on every move of the playhead.
  const timeline = useMemo<TimelineItem[]>(
    () =>
      [
        ...(events.data ?? []).map((e) => ({ at: e.relMs ?? 0, kind: "event" as const, e })),
        ...(annotations.data ?? []).map((m) => ({ at: m.relMs, kind: "annotation" as const, m })),
      ].sort((a, b) => a.at - b.at),
    [events.data, annotations.data],
  );
  const deviations = useMemo(
    () =>
      (events.data ?? [])
        .filter((e) => e.deviation && e.relMs !== null)
        .map((e) => ({ at: e.relMs!, kind: String(e.deviation) })),
    [events.data],
  );
  if (trial.isPending || events.isPending) return <Spinner label="Loading the trial…" />;
  if (trial.error || events.error) return <Problem error={trial.error ?? events.error} />;
  const t = trial.data;
  const r = report!;
  const movedBy = new Map(visits.map((v) => [v.seq, moveWords(v.move)]));
  // What an event in the list is about: its action (with the answer recorded), else its step (with what moved
  // the trial there); a robot's problem, in its own words; what the robot sensed, by its own clock.
  const about = (e: object) => {
    const { stepName, actionName } = named!.of(e);
    const problem = e as { type?: string; text?: string; seq?: number };
    const answer = answerOf(e);
    if (actionName !== undefined) return answer === undefined ? actionName : `${actionName}: “${answer}”`;
    const moved = problem.type === "step.entered" ? movedBy.get(problem.seq!) : undefined;
    if (stepName !== undefined) return moved ? `${stepName}, by ${moved}` : stepName;
    if (problem.type === "robot.sensed") {
      const { event, at } = e as { event: string; at: number };
      return `${event}, sensed at ${clockTime(new Date(at))} by the robot's clock`;
    }
    return problem.type === "robot.problem" ? problem.text : undefined;
  };
  // One time axis for the timeline and the robot's state: to the last event, annotation or sample.
  const endMs = Math.max(timeline.at(-1)?.at ?? 0, (samples.data ?? []).at(-1)?.relMs ?? 0);
  const gaps = recordingGaps(recording.parts, endMs);
  // A moment of the trial chosen on the timeline: the recording goes there, or (with none) the replay's playhead.
  const seekTo = (ms: number) => {
    if (recording.current) recording.seek(ms);
    else setPlayheadMs(ms);
  };
  // The row the playhead is in: the last one at or before it.
  const current = playheadMs === null ? -1 : timeline.findLastIndex((item) => item.at <= playheadMs);
  return (
    <div className="space-y-6">
      <div className="flex flex-wrap items-center gap-3">
        <Link href={`/studies/${t.studyId}`} className="text-sm text-slate-500 hover:text-slate-800">
          ← Study
        </Link>
        <h1 className="text-xl font-semibold">
          Analysis · {t.experimentName} · {t.participantCode ?? "no participant"}
        </h1>
        {t.isRehearsal && <Badge tone="amber">rehearsal</Badge>}
        {/* With its zone: the exports' times are in UTC, and this is where they are matched against. */}
        <span className="text-sm text-slate-600" data-testid="trial-started">
          {t.t0 ? `started ${clockDateTime(t.t0)}` : "not started"}
        </span>
        <span className="ml-auto flex gap-3 text-sm">
          <a className="font-medium text-brand-600 hover:underline" href={`/api/trials/${trialId}/export?format=csv`}>
            Download events (CSV)
          </a>
          <a className="font-medium text-brand-600 hover:underline" href={`/api/trials/${trialId}/export?format=json`}>
            Download trial record (JSON)
          </a>
          <a className="font-medium text-brand-600 hover:underline" href={`/api/trials/${trialId}/export?format=codes`}>
            Download codes (CSV)
          </a>
          <a className="font-medium text-brand-600 hover:underline" href={`/api/trials/${trialId}/export?format=eaf`}>
            ELAN (.eaf)
          </a>
          <a
            className="font-medium text-brand-600 hover:underline"
            href={`/api/trials/${trialId}/export?format=samples`}
          >
            Robot samples (CSV)
          </a>
          <a className="font-medium text-brand-600 hover:underline" href={`/api/trials/${trialId}/export?format=mcap`}>
            MCAP (Foxglove)
          </a>
        </span>
      </div>
      <TrialPeople
        wizardName={t.wizardName}
        createdByName={t.createdByName}
        started={events.data.some((e) => e.type === "trial.started")}
      />
      <div className="grid gap-4 sm:grid-cols-4">
        <Figure label="Execution fidelity" value={`${r.executionFidelity} %`} />
        <Figure label="Executed / planned" value={`${r.totals.executed} / ${r.totals.planned}`} />
        <Figure label="Deviations" value={String(Object.values(r.deviations).reduce((a, b) => a + b, 0))} />
        <Figure label="Branches by answer / by hand" value={`${r.branches.byLogic} / ${r.branches.byHand}`} />
        {/* Only in a trial that waited for the robot: who ended its waits, and how often a time limit moved it. */}
        {r.moves.senses + r.moves.go_on > 0 && (
          <Figure
            label="Moves by the robot's senses / a timer / the wizard's go on"
            value={`${r.moves.senses} / ${r.moves.timer} / ${r.moves.go_on}`}
          />
        )}
      </div>
      <RecordingPlayer recording={recording} gaps={gaps} onTime={setPlayheadMs} />
      {(t.status === "completed" || t.status === "aborted") && (
        <ReplayControl
          trialId={trialId}
          playheadMs={playheadMs}
          recording={recording.current}
          video={recording.video}
        />
      )}
      <QuestionnaireAnswers trialId={trialId} studyId={t.studyId} />
      <StepPath visits={visits} stepName={(stepId) => named!.step(stepId)} />
      <LoopIterations report={r} stepName={(stepId) => named!.step(stepId)} />
      <section aria-label="Planned versus executed">
        <h2 className="mb-2 text-lg font-semibold">Planned versus executed</h2>
        <PlannedTable report={r} />
      </section>
      <section aria-label="Timeline">
        <h2 className="mb-2 text-lg font-semibold">Timeline</h2>
        <TimelineChart
          report={r}
          deviations={deviations}
          annotations={(annotations.data ?? []).map((m) => ({ at: m.relMs, label: m.label }))}
          recording={recording.parts.length ? { parts: recording.parts, gaps } : null}
          endMs={endMs}
          playheadMs={playheadMs}
          onSeek={seekTo}
        />
        <EventList items={timeline} current={current} about={about} onSeek={seekTo} />
      </section>
      <AnnotationsEditor trialId={trialId} annotations={annotations.data ?? []} playheadMs={playheadMs} />
      {t.myRole !== "wizard" && (
        <>
          <CodeTiers trialId={trialId} playheadMs={playheadMs} />
          <AgreementPanel studyId={t.studyId} trialId={trialId} />
        </>
      )}
      {samples.data && samples.data.length > 0 && (
        <JointAngles
          samples={samples.data as Array<{ relMs: number; data: unknown }>}
          endMs={endMs}
          playheadMs={playheadMs}
          onSeek={seekTo}
        />
      )}
    </div>
  );
}

function Figure({ label, value }: { label: string; value: string }) {
  return (
    <Card className="p-4">
      <div className="text-xs text-slate-500">{label}</div>
      <div className="mt-1 text-2xl font-semibold" data-testid={`figure-${label}`}>
        {value}
      </div>
    </Card>
  );
}
