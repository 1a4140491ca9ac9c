"use client";
// A rehearsal without a trial: choose an answer for each question and what
// happens at each wait (an event the robot senses, the wizard's go on), or,
// where there is a time limit, let the time run out, and read the exact sequence
// the robot would perform, walked by the trial engine itself, so what is
// shown here is what a trial of this draft would do, as the chosen condition
// would run it (its variants).
import { useMemo, useState } from "react";
import { inCondition } from "@/core/protocol/variants";
import type { DesignAction, DesignDraft } from "@/core/designer/types";
import { awaitedEvents } from "@/core/protocol/flow";
import { answerOptions, rehearse } from "@/core/trial";
import { Field, NativeSelect } from "@/ui/field";

/** The choice that lets a question's or a step's time limit run out; the designer gives answers generated ids, never this word. */
const RUN_OUT = "run-out";

export function RehearsalPreview({
  draft,
  actionName,
  eventName,
  blocked,
  conditions,
}: {
  draft: DesignDraft;
  /** The study's conditions that run this experiment: the preview may run as one of them. */
  conditions: string[];
  actionName: (action: DesignAction) => string;
  /** What the robot's plugin calls one of its events ("Head touched"). */
  eventName: (id: string) => string;
  /** Why the draft cannot be walked yet (its errors), if so. */
  blocked: string | null;
}) {
  const questions = useMemo(
    () =>
      draft.steps.flatMap((step) =>
        step.actions.filter((a) => a.type === "record_answer").map((action) => ({ step, action })),
      ),
    [draft],
  );
  const waits = useMemo(
    () =>
      draft.steps.flatMap((step) =>
        step.actions.filter((a) => a.type === "wait_for").map((action) => ({ step, action })),
      ),
    [draft],
  );
  const limited = useMemo(() => draft.steps.filter((step) => step.timeLimit), [draft]);
  const [choices, setChoices] = useState<Record<string, string>>({});
  /** The steps and questions whose time limit runs out in this rehearsal. */
  const [runOut, setRunOut] = useState<ReadonlySet<string>>(new Set());
  const letRunOut = (id: string, yes: boolean) => {
    const next = new Set(runOut);
    if (yes) next.add(id);
    else next.delete(id);
    setRunOut(next);
  };
  // "": the design as every condition without a variant runs it.
  const [condition, setCondition] = useState("");
  const result = useMemo(() => {
    if (blocked) return null;
    try {
      return { ok: true as const, rehearsal: rehearse(inCondition(draft, condition || null), choices, runOut) };
    } catch (e) {
      return { ok: false as const, reason: (e as Error).message };
    }
  }, [draft, choices, runOut, blocked, condition]);

  return (
    <section aria-label="Rehearsal preview" className="space-y-4">
      <p className="text-sm text-slate-700">
        Choose an answer to each question and what the robot senses at each wait, or let a time limit run out, to see
        what the robot would do, step by step. Nothing is sent to a robot.
      </p>
      {conditions.length > 0 && (
        <Field label="As condition">
          {(p) => (
            <NativeSelect {...p} value={condition} onChange={(e) => setCondition(e.target.value)}>
              <option value="">The shared design (no condition's variants)</option>
              {conditions.map((c) => (
                <option key={c} value={c}>
                  {c}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
      )}
      {questions.length + waits.length + limited.length > 0 && (
        <div className="grid gap-3 sm:grid-cols-2">
          {questions.map(({ step, action }) => (
            <Field key={action.id} label={`${step.name}: ${actionName(action)}`}>
              {(p) => (
                <NativeSelect
                  {...p}
                  value={runOut.has(action.id) ? RUN_OUT : (choices[action.id] ?? answerOptions(action)[0]?.id ?? "")}
                  onChange={(e) => {
                    letRunOut(action.id, e.target.value === RUN_OUT);
                    if (e.target.value !== RUN_OUT) setChoices({ ...choices, [action.id]: e.target.value });
                  }}
                >
                  {answerOptions(action).map((o) => (
                    <option key={o.id} value={o.id}>
                      {o.label}
                    </option>
                  ))}
                  {action.timeLimit && (
                    <option value={RUN_OUT}>No answer: let the time run out ({action.timeLimit.seconds} s)</option>
                  )}
                </NativeSelect>
              )}
            </Field>
          ))}
          {waits.map(({ step, action }) => (
            <Field key={action.id} label={`${step.name}: ${actionName(action)}`}>
              {(p) => (
                <NativeSelect
                  {...p}
                  value={runOut.has(action.id) ? RUN_OUT : (choices[action.id] ?? "")}
                  onChange={(e) => {
                    letRunOut(action.id, e.target.value === RUN_OUT);
                    setChoices({ ...choices, [action.id]: e.target.value === RUN_OUT ? "" : e.target.value });
                  }}
                >
                  <option value="">Nothing sensed: the wizard goes on</option>
                  {awaitedEvents(action).map((a) => (
                    <option key={a.id} value={a.id}>
                      The robot senses: {eventName(a.event)}
                    </option>
                  ))}
                  {action.timeLimit && (
                    <option value={RUN_OUT}>Nothing sensed: let the time run out ({action.timeLimit.seconds} s)</option>
                  )}
                </NativeSelect>
              )}
            </Field>
          ))}
          {limited.map((step) => (
            <Field key={step.id} label={`${step.name}: its time limit`}>
              {(p) => (
                <NativeSelect
                  {...p}
                  value={runOut.has(step.id) ? RUN_OUT : ""}
                  onChange={(e) => letRunOut(step.id, e.target.value === RUN_OUT)}
                >
                  <option value="">The wizard moves on in time</option>
                  <option value={RUN_OUT}>Let the time run out ({step.timeLimit!.seconds} s)</option>
                </NativeSelect>
              )}
            </Field>
          ))}
        </div>
      )}
      {blocked && <p className="text-sm text-amber-900">{blocked}</p>}
      {result && !result.ok && <p className="text-sm text-amber-900">The preview stopped: {result.reason}</p>}
      {result?.ok && (
        <ol aria-label="What the robot would do" className="space-y-2">
          {result.rehearsal.steps.map((step, i) => (
            <li key={`${step.stepId}-${i}`} className="rounded-md border border-slate-200 bg-white p-3">
              <p className="text-sm font-semibold">
                {step.number}. {step.name}
                {step.again && (
                  <span className="ml-2 font-normal text-violet-800">back round the loop, time {step.again}</span>
                )}
              </p>
              <ol className="mt-1 list-inside list-decimal text-sm text-slate-800">
                {step.units.map((unit) => (
                  <li key={unit.map((a) => a.id).join()} data-rehearsed={unit.map((a) => a.id).join(" ")}>
                    {unit.map((a) => actionName(a as DesignAction)).join(" + together: ")}
                    {/* Names shorten speech; the preview shows what the robot would say, word for word. */}
                    {unit.map((a) =>
                      typeof a.parameters.text === "string" &&
                      !actionName(a as DesignAction).includes(a.parameters.text) ? (
                        <span key={a.id} className="block pl-4 text-slate-600">
                          “{a.parameters.text}”
                        </span>
                      ) : null,
                    )}
                  </li>
                ))}
              </ol>
              {step.answer && <p className="mt-1 text-xs text-brand-800">Answer: {step.answer.label}</p>}
              {step.sensed && (
                <p className="mt-1 text-xs text-brand-800">The robot sensed: {eventName(step.sensed.event)}</p>
              )}
              {step.timeout && (
                <p className="mt-1 text-xs text-amber-900">
                  {step.timeout.question ? "No answer" : "The step went on"}: its {step.timeout.seconds} s ran out.
                </p>
              )}
            </li>
          ))}
          <li className="text-sm text-slate-700">
            {result.rehearsal.ending === "completed"
              ? "The trial ends."
              : "These answers keep the trial in a loop: it never ends. Choose another answer, or change where a step leads."}
          </li>
        </ol>
      )}
    </section>
  );
}
