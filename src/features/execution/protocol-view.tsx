"use client";
// The protocol as both the wizard and observers see it: the way taken, the
// current step, what comes next, and each action's status and timing from
// the event log; an action that was not done says why beside its badge.
import { actionName, type ActionNames } from "@/core/designer/action-name";
import { WAITS_FOR_CHOICE } from "@/core/designer/blocks";
import { type ActionState, pathTaken, type TrialProtocol, type TrialState, upcoming } from "@/core/trial";
import { OUTCOME_WORDS } from "@/core/trial/outcomes";
import { cn } from "@/ui/cn";
import { Badge, type Tone } from "@/ui/surface";

const STATUS: Record<ActionState["status"], { label: string; tone: Tone }> = {
  waiting: { label: "waiting", tone: "slate" },
  requested: { label: "sent", tone: "blue" },
  running: { label: "running", tone: "blue" },
  done: { label: "done", tone: "green" },
  failed: { label: OUTCOME_WORDS.failed, tone: "red" },
  not_sent: { label: OUTCOME_WORDS.not_sent, tone: "slate" },
  unknown: { label: OUTCOME_WORDS.unknown, tone: "amber" },
  timed_out: { label: "timed out", tone: "red" },
  skipped: { label: "skipped", tone: "amber" },
};

/**
 * The way through: the steps this trial has taken, the current one
 * highlighted, and what comes next — not every step of every branch. A jump
 * elsewhere (a deviation) is one disclosure away for the wizard.
 */
export function StepList({
  protocol,
  state,
  onJump,
}: {
  protocol: TrialProtocol;
  state: TrialState;
  onJump?: (stepId: string) => void;
}) {
  const taken = pathTaken(protocol, state);
  const next = upcoming(protocol, state);
  const number = (id: string) => protocol.steps.findIndex((s) => s.id === id) + 1;
  return (
    <div className="space-y-3 text-sm">
      <ol className="space-y-1" aria-label="Steps taken">
        {taken.map((step, i) => {
          const current = i === taken.length - 1 && step.id === state.currentStepId;
          return (
            <li
              key={`${step.id}-${i}`}
              aria-current={current ? "step" : undefined}
              className={cn(
                "rounded-md px-3 py-2",
                current ? "bg-brand-600 font-semibold text-white" : "text-slate-600",
              )}
            >
              {number(step.id)}. {step.name}
            </li>
          );
        })}
      </ol>
      <div aria-label="Next step" role="note" className="rounded-md border border-dashed border-slate-300 px-3 py-2">
        <span className="text-xs font-semibold uppercase tracking-wide text-slate-600">Next</span>
        {next.kind === "step" && (
          <p>
            {number(next.step.id)}. {next.step.name}
          </p>
        )}
        {next.kind === "end" && <p>End of the trial</p>}
        {next.kind === "answer" && (
          <ul>
            {next.routes.map((r) => (
              <li key={r.label}>
                “{r.label}” → {r.step ? `${number(r.step.id)}. ${r.step.name}` : "not set"}
              </li>
            ))}
          </ul>
        )}
      </div>
      {onJump && state.status === "in_progress" && (
        <details>
          <summary className="cursor-pointer text-xs text-brand-700 pointer-coarse:py-3.5">
            Jump to another step (a deviation)
          </summary>
          <ul className="mt-1 space-y-1">
            {protocol.steps.map((step) =>
              step.id === state.currentStepId ? null : (
                <li key={step.id}>
                  <button
                    type="button"
                    className="text-left text-xs text-brand-700 underline-offset-2 hover:underline pointer-coarse:min-h-11"
                    onClick={() => onJump(step.id)}
                  >
                    Jump to {step.name}
                  </button>
                </li>
              ),
            )}
          </ul>
        </details>
      )}
    </div>
  );
}

export function StepActions({
  protocol,
  names,
  state,
  problems,
  onTrigger,
  notes = false,
}: {
  protocol: TrialProtocol;
  names: ActionNames;
  state: TrialState;
  /** Why actions were not done, by id (actionProblems). */
  problems: Record<string, string>;
  onTrigger?: (actionId: string) => void;
  /** Show each action's note for the wizard (the wizard's view; observers watch what happens). */
  notes?: boolean;
}) {
  const step = protocol.steps.find((s) => s.id === state.currentStepId);
  if (!step) return <p className="text-slate-500">The trial has not started.</p>;
  return (
    <section aria-label="Current step">
      <h2 className="text-xl font-semibold" data-testid="current-step">
        {step.name}
      </h2>
      {step.description?.trim() && (
        <p className="mt-1 max-w-prose whitespace-pre-line text-slate-700" data-testid="step-description">
          {step.description.trim()}
        </p>
      )}
      <ul className="mt-3 divide-y divide-slate-100 rounded-lg border border-slate-200 bg-white">
        {step.actions.map((a) => {
          const s = state.actions[a.id]!;
          const took =
            s.finishedAt != null && s.requestedAt != null
              ? `${((s.finishedAt - s.requestedAt) / 1000).toFixed(1)} s`
              : "";
          return (
            <li
              key={a.id}
              className="flex flex-wrap items-center gap-3 px-4 py-2 text-sm"
              data-testid={`action-${a.id}`}
            >
              <Badge tone={STATUS[s.status].tone}>{STATUS[s.status].label}</Badge>
              {/* A long speech is cut in its name; the whole text is a hover away (and below, for the wizard). */}
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
                {a.parallelGroup && <span className="ml-2 text-xs text-slate-500">together</span>}
              </span>
              <span className="text-xs tabular-nums text-slate-500">{took}</span>
              {onTrigger &&
                s.status === "waiting" &&
                state.status === "in_progress" &&
                !WAITS_FOR_CHOICE.has(a.type) && (
                  <button
                    type="button"
                    className="text-xs text-brand-600 hover:underline pointer-coarse:min-h-11 pointer-coarse:px-2"
                    onClick={() => onTrigger(a.id)}
                  >
                    {/* The action's name is heard, not shown: its row already shows it. */}
                    run<span className="sr-only"> {actionName(a, names)}</span> now
                  </button>
                )}
              <WhyNotDone text={problems[a.id]} />
              {/* The wizard reads the whole line the robot will say, not its cut name: they must hear whether it was said. */}
              {notes &&
                a.type !== "wizard_instruction" &&
                typeof a.parameters.text === "string" &&
                !actionName(a, names).includes(a.parameters.text.trim()) && (
                  <p className="basis-full whitespace-pre-line text-slate-700" data-testid="line-text">
                    {a.parameters.text}
                  </p>
                )}
              {notes && a.note?.trim() && (
                <p
                  className="basis-full whitespace-pre-line rounded-md border-l-4 border-amber-400 bg-amber-50 px-3 py-1.5 text-amber-900"
                  data-testid="action-note"
                >
                  <span className="sr-only">Note for the wizard: </span>
                  {a.note.trim()}
                </p>
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
  problems,
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
  problems: Record<string, string>;
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
            <li key={e.actionId} className="flex flex-wrap items-center gap-3 px-4 py-2 text-sm">
              {s && <Badge tone={STATUS[s.status].tone}>{STATUS[s.status].label}</Badge>}
              <span>{actionName({ type: e.actionType ?? "", parameters: e.parameters }, names)}</span>
              <WhyNotDone text={problems[e.actionId!]} />
            </li>
          );
        })}
      </ul>
    </section>
  );
}

/** The reason, on its own line under the action; announced when it appears. */
function WhyNotDone({ text }: { text: string | undefined }) {
  if (!text) return null;
  return (
    <p role="alert" className="basis-full text-xs text-red-700" data-testid="action-problem">
      {text}
    </p>
  );
}
