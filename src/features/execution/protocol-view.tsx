"use client";
// The protocol as both the wizard and observers see it: steps, the current
// one highlighted, and each action's status and timing from the event log.
import { actionName, type ActionNames } from "@/core/designer/action-name";
import type { ActionState, TrialProtocol, TrialState } from "@/core/trial";
import { cn } from "@/ui/cn";
import { Badge, type Tone } from "@/ui/surface";

const STATUS: Record<ActionState["status"], { label: string; tone: Tone }> = {
  waiting: { label: "waiting", tone: "slate" },
  requested: { label: "sent", tone: "blue" },
  running: { label: "running", tone: "blue" },
  done: { label: "done", tone: "green" },
  failed: { label: "failed", tone: "red" },
  timed_out: { label: "timed out", tone: "red" },
  skipped: { label: "skipped", tone: "amber" },
};

export function StepList({
  protocol,
  state,
  onJump,
}: {
  protocol: TrialProtocol;
  state: TrialState;
  onJump?: (stepId: string) => void;
}) {
  return (
    <ol className="space-y-1" aria-label="Steps">
      {protocol.steps.map((step, i) => {
        const current = step.id === state.currentStepId;
        const done = step.actions.length > 0 && step.actions.every((a) => state.actions[a.id]?.status !== "waiting");
        return (
          <li
            key={step.id}
            aria-current={current ? "step" : undefined}
            className={cn(
              "rounded-md px-3 py-2 text-sm",
              current ? "bg-brand-600 font-semibold text-white" : done ? "text-slate-400" : "text-slate-700",
            )}
          >
            {i + 1}. {step.name}
            {onJump && !current && state.status === "in_progress" && (
              <button
                type="button"
                className="ml-2 text-xs text-brand-600 underline-offset-2 hover:underline"
                aria-label={`Jump to ${step.name}`}
                onClick={() => onJump(step.id)}
              >
                jump
              </button>
            )}
          </li>
        );
      })}
    </ol>
  );
}

export function StepActions({
  protocol,
  names,
  state,
  onTrigger,
}: {
  protocol: TrialProtocol;
  names: ActionNames;
  state: TrialState;
  onTrigger?: (actionId: string) => void;
}) {
  const step = protocol.steps.find((s) => s.id === state.currentStepId);
  if (!step) return <p className="text-slate-500">The trial has not started.</p>;
  return (
    <section aria-label="Current step">
      <h2 className="text-xl font-semibold" data-testid="current-step">
        {step.name}
      </h2>
      <ul className="mt-3 divide-y divide-slate-100 rounded-lg border border-slate-200 bg-white">
        {step.actions.map((a) => {
          const s = state.actions[a.id]!;
          const took =
            s.finishedAt != null && s.requestedAt != null
              ? `${((s.finishedAt - s.requestedAt) / 1000).toFixed(1)} s`
              : "";
          return (
            <li key={a.id} className="flex items-center gap-3 px-4 py-2 text-sm" data-testid={`action-${a.id}`}>
              <Badge tone={STATUS[s.status].tone}>{STATUS[s.status].label}</Badge>
              {/* A long speech is cut in its name; the whole text is a hover away. */}
              <span className="flex-1" title={typeof a.parameters.text === "string" ? a.parameters.text : undefined}>
                {a.type === "wizard_instruction" ? (
                  <strong>Instruction: {String(a.parameters.text ?? a.name)}</strong>
                ) : (
                  actionName(a, names)
                )}
                {/* A labelled pause names itself ("Hold still"); the wizard still needs its length. */}
                {a.type === "pause" && a.name?.trim() && (
                  <span className="ml-2 text-xs text-slate-500">{Number(a.parameters.seconds ?? 0)} s</span>
                )}
                {a.parallelGroup && <span className="ml-2 text-xs text-slate-400">together</span>}
              </span>
              <span className="text-xs tabular-nums text-slate-500">{took}</span>
              {onTrigger &&
                s.status === "waiting" &&
                state.status === "in_progress" &&
                !["record_answer", "branch"].includes(a.type) && (
                  <button
                    type="button"
                    className="text-xs text-brand-600 hover:underline"
                    aria-label={`Run ${actionName(a, names)} now`}
                    onClick={() => onTrigger(a.id)}
                  >
                    run now
                  </button>
                )}
            </li>
          );
        })}
      </ul>
    </section>
  );
}

/** Actions the wizard sent off script, with their status: deviations, visible as they happen. */
export function OffScript({
  events,
  names,
  state,
}: {
  events: Array<{
    type: string;
    actionId?: string;
    actionType?: string;
    scripted?: boolean;
    parameters?: Record<string, unknown>;
  }>;
  names: ActionNames;
  state: TrialState;
}) {
  const unscripted = events.filter((e) => e.type === "action.requested" && e.scripted === false);
  if (!unscripted.length) return null;
  return (
    <section aria-label="Off script">
      <h3 className="mb-2 text-sm font-semibold text-amber-800">Off script</h3>
      <ul className="divide-y divide-slate-100 rounded-lg border border-amber-200 bg-amber-50/40">
        {unscripted.map((e) => {
          const s = state.actions[e.actionId!];
          return (
            <li key={e.actionId} className="flex items-center gap-3 px-4 py-2 text-sm">
              {s && <Badge tone={STATUS[s.status].tone}>{STATUS[s.status].label}</Badge>}
              <span>{actionName({ type: e.actionType ?? "", parameters: e.parameters }, names)}</span>
            </li>
          );
        })}
      </ul>
    </section>
  );
}
