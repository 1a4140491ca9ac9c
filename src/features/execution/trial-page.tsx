"use client";
import { useQuery } from "@tanstack/react-query";
import Link from "next/link";
import { useCallback, useEffect, useMemo, useState } from "react";
import { studyRoleMay } from "@/core/access/policy";
import type { ActionNames } from "@/core/designer/action-name";
import type { EventNames } from "@/core/plugins/event-names";
import { actionProblems, type TrialProtocol, type TrialState } from "@/core/trial";
import { indicators } from "@/core/trial/connections";
import { useTRPC } from "@/lib/trpc";
import { Problem } from "@/ui/problem";
import { Badge, Card, Spinner, STATUS_TONE } from "@/ui/surface";
import { BrowserAudio } from "./browser-audio";
import { SendVideo, WatchVideo } from "./live-video-panel";
import { RobotCamera } from "./robot-camera";
import { CodeAfterwards } from "../coding/code-afterwards";
import { LiveCodingPanel } from "../coding/live-coding-panel";
import { AnnotateForm, AnnotationList, Watching } from "./observer-panel";
import { OffScript, StepActions, StepList } from "./protocol-view";
import { TrialQuestionnaires } from "@/features/questionnaires/trial-questionnaires";
import { RecordingPanel } from "@/features/recording/recording-panel";
import { RobotStatePanel } from "./robot-state-panel";
import { TimeLimits } from "./time-limits";
import { TrialClock } from "./trial-clock";
import { TrialPeople } from "./trial-people";
import { useDatabaseState } from "./use-database-state";
import { useTrialSocket } from "./use-trial-socket";
import { SHORTCUTS, WizardControls } from "./wizard-controls";

export function TrialPage({ trialId }: { trialId: string }) {
  const trpc = useTRPC();
  const trial = useQuery(trpc.trials.get.queryOptions({ trialId }));
  if (trial.isPending) return <Spinner />;
  if (trial.error) return <Problem error={trial.error} />;
  return (
    <LiveTrial
      trial={trial.data}
      protocol={trial.data.protocol as TrialProtocol}
      refresh={() => void trial.refetch()}
    />
  );
}

type Trial = {
  id: string;
  status: TrialState["status"];
  studyId: string;
  experimentName: string;
  participantId: string | null;
  participantCode: string | null;
  isRehearsal: boolean;
  version: number | null;
  wizardId: string | null;
  wizardName: string | null;
  createdByName: string | null;
  myRole: "owner" | "researcher" | "wizard" | "observer";
  actionNames: ActionNames;
  eventNames: EventNames;
};

function LiveTrial({ trial, protocol, refresh }: { trial: Trial; protocol: TrialProtocol; refresh: () => void }) {
  const live = useTrialSocket(trial.id, protocol);
  const database = useDatabaseState();
  // The runtime decides (a wizard runs only the trials assigned to them); until it has said, the study role guides.
  const wizard = live.mayRun ?? studyRoleMay(trial.myRole, "trial.run");
  // Without the runtime nothing reaches the trial: the controls that would send are off (the wizard's say why).
  const send = wizard && live.connected;
  const started = live.events.find((e) => e.type === "trial.started");
  const problems = useMemo(() => actionProblems(live.events), [live.events]);
  // A finished trial's log is results: whoever may not read them (a wizard) gets no events, so the
  // socket's state would say "scheduled" and offer Start. The trial's row says how it ended.
  const rowEnded = trial.status === "completed" || trial.status === "aborted";
  const logHidden = rowEnded && live.state.status === "scheduled";
  const status = logHidden ? trial.status : live.state.status;
  const ended = status === "completed" || status === "aborted";
  const { command } = live;
  // The camera and microphone the wizard records: also what those watching see live.
  const [camera, setCamera] = useState<MediaStream | null>(null);
  // Starting an unassigned trial records its starter as the wizard: read who that was.
  const claimed = Boolean(started) && trial.wizardId === null;
  // biome-ignore lint/correctness/useExhaustiveDependencies: refresh is a new function on every render; once per start is enough
  useEffect(() => {
    if (claimed) refresh();
  }, [claimed]);
  const logRecording = useCallback(
    (recordingId: string, offsetMs: number) => void command({ kind: "recording", recordingId, offsetMs }),
    [command],
  );
  return (
    <div className="space-y-4">
      <div className="flex flex-wrap items-center gap-3">
        <Link href={`/studies/${trial.studyId}`} className="text-sm text-slate-500 hover:text-slate-800">
          ← Study
        </Link>
        <h1 className="text-xl font-semibold">
          {trial.experimentName} · {trial.participantCode ?? "no participant"}
        </h1>
        {trial.isRehearsal ? <Badge tone="amber">rehearsal</Badge> : <Badge>version {trial.version}</Badge>}
        <Badge tone={STATUS_TONE[status]}>
          <span data-testid="trial-status">{status.replace("_", " ")}</span>
        </Badge>
        {/* Red only while it holds a live trial; once the trial has ended it is history. */}
        {live.state.emergencyStopped &&
          (ended ? (
            <Badge>
              <span data-testid="emergency-stop">emergency stop used</span>
            </Badge>
          ) : (
            <Badge tone="red">
              <span data-testid="emergency-stop">emergency stop</span>
            </Badge>
          ))}
        <span className="ml-auto flex items-center gap-4">
          {indicators({ runtime: live.runtime, robot: live.robot, database, ended }).map(({ what, state, tone }) => (
            <Badge key={what} tone={tone}>
              {/* One item: a badge is a flex box, where a space between two items would collapse. */}
              <span>
                {what} <span data-testid={`${what}-status`}>{state}</span>
              </span>
            </Badge>
          ))}
          <TrialClock startedAt={started?.serverTime ?? null} stopped={ended} />
        </span>
      </div>
      <TrialPeople wizardName={trial.wizardName} createdByName={trial.createdByName} started={Boolean(started)} />
      {live.notice && <Problem error={{ message: live.notice }} />}
      {logHidden && (
        <Card className="p-4 text-sm" data-testid="trial-ended">
          This trial has ended. What happened in it is part of the study&apos;s results, which your role in this study
          does not show.
        </Card>
      )}
      {ended && studyRoleMay(trial.myRole, "data.read") && (
        <Link href={`/trials/${trial.id}/analysis`} className="inline-block font-medium text-brand-600 hover:underline">
          Open the analysis of this trial →
        </Link>
      )}
      <div className="grid grid-cols-1 gap-6 lg:grid-cols-[14rem_1fr_20rem]">
        <Card className="p-3">
          <StepList
            protocol={protocol}
            state={live.state}
            onJump={send ? (stepId) => void live.command({ kind: "jump", stepId }) : undefined}
          />
        </Card>
        <div className="space-y-6">
          {!logHidden && <TimeLimits protocol={protocol} state={live.state} startedAt={started?.serverTime ?? null} />}
          {!logHidden && (
            <StepActions
              protocol={protocol}
              names={trial.actionNames}
              state={live.state}
              problems={problems}
              onTrigger={send ? (actionId) => void live.command({ kind: "trigger", actionId }) : undefined}
              notes={wizard}
            />
          )}
          {wizard && <BrowserAudio events={live.events} state={live.state} send={live.command} />}
          <OffScript events={live.events} names={trial.actionNames} state={live.state} problems={problems} />
          {wizard && !logHidden && (
            <WizardControls
              protocol={protocol}
              names={trial.actionNames}
              eventNames={trial.eventNames}
              state={live.state}
              runtime={live.runtime}
              send={live.command}
              events={live.events}
            />
          )}
        </div>
        <div className="space-y-4">
          {wizard && (
            <RobotStatePanel name={live.robot?.name} state={live.robotState} notStarted={status === "scheduled"} />
          )}
          <Watching viewers={live.viewers} />
          {wizard && (
            <RecordingPanel
              trialId={trial.id}
              startedAt={started?.serverTime ?? null}
              ended={ended}
              logStart={logRecording}
              onStream={setCamera}
            />
          )}
          {wizard && <SendVideo video={live.video} viewers={live.viewers} stream={camera} />}
          {!wizard && <WatchVideo video={live.video} viewers={live.viewers} />}
          <RobotCamera onCamera={live.onCamera} ended={ended} />
          {wizard && trial.participantId && !trial.isRehearsal && (
            <TrialQuestionnaires studyId={trial.studyId} trialId={trial.id} participantId={trial.participantId} />
          )}
          {!wizard && !ended && <LiveCodingPanel trialId={trial.id} codes={live.codes} send={live.code} />}
          {!wizard && ended && <CodeAfterwards trialId={trial.id} />}
          {!wizard && <AnnotateForm annotate={live.annotate} />}
          <AnnotationList annotations={live.annotations} />
          {wizard && (
            <Card className="p-4 text-sm">
              <h2 className="mb-2 font-semibold">Keyboard</h2>
              <dl className="grid grid-cols-[4rem_1fr] gap-y-1">
                {SHORTCUTS.map(([key, what]) => (
                  <div key={key} className="contents">
                    <dt>
                      <kbd className="rounded border border-slate-300 bg-slate-50 px-1.5 font-mono text-xs">{key}</kbd>
                    </dt>
                    <dd className="text-slate-600">{what}</dd>
                  </div>
                ))}
              </dl>
            </Card>
          )}
        </div>
      </div>
    </div>
  );
}
