"use client";
// The properties of what is selected, always beside the timeline. Every form
// comes from the block's JSON Schema; answers and branch targets have their
// own editors, so nobody types JSON or an id.
import { ArrowDown, ArrowUp, Plus, Trash2, X } from "lucide-react";
import { type Block, OWN_EDITORS, WAITS_FOR_CHOICE } from "@/core/designer/blocks";
import { commands } from "@/core/designer/model";
import { changedParameters } from "@/core/designer/changed-parameters";
import type { Command } from "@/core/designer/history";
import { locateAction, locateStep } from "@/core/designer/draft";
import type { DesignIssue } from "@/core/designer/validate";
import type { DesignAction, DesignDraft } from "@/core/designer/types";
import type { AudioPlayer, ParameterSchema, RobotEvent } from "@/core/plugins";
import { newId } from "@/lib/new-id";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect, Textarea } from "@/ui/field";
import { SchemaForm } from "@/ui/schema-form";
import { AudioChooser } from "./audio-chooser";
import { ThenField } from "./then-field";
import { TimeLimitField } from "./time-limit-field";
import type { Selection } from "./protocol-timeline";
import { WaitEditor } from "./wait-editor";
import { StepVariantsField } from "./step-variants-field";
import { VariantsField } from "./variants-field";

interface Props {
  draft: DesignDraft;
  selection: Selection;
  issues: DesignIssue[];
  blockFor: (type: string) => Block | undefined;
  run: (c: Command) => void;
  onMove: (delta: -1 | 1) => void;
  onDelete: () => void;
  /** For "Play audio": the study whose sounds it plays, and who plays them on this robot. */
  studyId: string;
  robotName: string;
  audioPlayer: AudioPlayer;
  /** What the experiment's robot senses, for a "Wait for". */
  robotEvents: RobotEvent[];
  /** The names of the study's conditions that run this experiment: an action or a step may vary for each. */
  conditions: string[];
}

export function PropertiesPanel(props: Props) {
  const { draft, selection } = props;
  const found = selection && findSelected(draft, selection);
  return (
    <section aria-label="Properties" className="rounded-lg border border-slate-200 bg-white p-4 shadow-sm">
      {!found ? (
        <p className="text-sm text-slate-500">Select a step or an action to see and edit its properties.</p>
      ) : found.kind === "step" ? (
        <StepProperties {...props} stepId={found.id} />
      ) : (
        <ActionProperties {...props} action={found.action} />
      )}
    </section>
  );
}

function findSelected(draft: DesignDraft, selection: NonNullable<Selection>) {
  try {
    if (selection.kind === "step") return { kind: "step" as const, id: locateStep(draft, selection.id).step.id };
    return { kind: "action" as const, action: locateAction(draft, selection.id).action };
  } catch {
    return null;
  }
}

function Toolbar({ what, onMove, onDelete }: { what: string; onMove: Props["onMove"]; onDelete: Props["onDelete"] }) {
  return (
    <div className="flex gap-1 border-t border-slate-100 pt-3">
      <Button variant="ghost" size="sm" onClick={() => onMove(-1)} title="Alt+↑" aria-label={`Move ${what} up`}>
        <ArrowUp className="h-4 w-4" aria-hidden /> Up
      </Button>
      <Button variant="ghost" size="sm" onClick={() => onMove(1)} title="Alt+↓" aria-label={`Move ${what} down`}>
        <ArrowDown className="h-4 w-4" aria-hidden /> Down
      </Button>
      <Button
        variant="ghost"
        size="sm"
        className="ml-auto text-red-700"
        onClick={onDelete}
        title="Delete"
        aria-label={`Delete ${what}`}
      >
        <Trash2 className="h-4 w-4" aria-hidden /> Delete
      </Button>
    </div>
  );
}

function StepProperties({
  draft,
  stepId,
  issues,
  blockFor,
  run,
  onMove,
  onDelete,
  conditions,
}: Props & { stepId: string }) {
  const { step, index } = locateStep(draft, stepId);
  const own = issues.filter((i) => i.stepId === stepId && !i.actionId);
  return (
    <div className="space-y-3">
      <h2 className="font-semibold">Step {index + 1}</h2>
      <Field label="Step name" required error={step.name.trim() ? undefined : "A step needs a name."}>
        {(p) => (
          <Input
            {...p}
            value={step.name}
            onChange={(e) => run(commands.updateStep(stepId, { name: e.target.value }))}
          />
        )}
      </Field>
      <Field label="Description" hint="For the researchers and the wizard; the participant never sees it.">
        {(p) => (
          <Textarea
            {...p}
            value={step.description}
            onChange={(e) => run(commands.updateStep(stepId, { description: e.target.value }))}
          />
        )}
      </Field>
      <AfterStep draft={draft} stepId={stepId} run={run} />
      <TimeLimitField
        draft={draft}
        stepId={stepId}
        limit={step.timeLimit}
        label="Time limit (seconds)"
        hint="The longest this step may last from when the trial enters it. Leave empty for no limit."
        onChange={(limit) => run(commands.setStepTimeLimit(stepId, limit))}
      />
      <StepVariantsField step={step} conditions={conditions} blockFor={blockFor} run={run} />
      <IssueList issues={own} />
      <Toolbar what="step" onMove={onMove} onDelete={onDelete} />
    </div>
  );
}

/** Where the step leads once its actions are done: how answers' steps rejoin a shared step, or a step asks again. */
function AfterStep({ draft, stepId, run }: Pick<Props, "draft" | "run"> & { stepId: string }) {
  const { step } = locateStep(draft, stepId);
  return (
    <ThenField
      draft={draft}
      stepId={stepId}
      after={step.after}
      label="Then"
      hint="Where the trial goes once this step's actions are done. Steps for different answers usually go to the step where the answers meet; going back asks again, at most the times you set."
      onChange={(after) => run(commands.setAfter(stepId, after))}
    />
  );
}

function ActionProperties({
  draft,
  action,
  issues,
  blockFor,
  run,
  onMove,
  onDelete,
  studyId,
  robotName,
  audioPlayer,
  robotEvents,
  conditions,
}: Props & { action: DesignAction }) {
  const block = blockFor(action.type);
  const { step, index } = locateAction(draft, action.id);
  const own = issues.filter((i) => i.actionId === action.id);
  const problems = own.filter((i) => i.parameter).map((i) => ({ parameter: i.parameter!, message: i.message }));
  const setParameters = (values: Record<string, unknown>) => {
    for (const [k, v] of changedParameters(action.parameters, values)) run(commands.setParameter(action.id, k, v));
  };
  return (
    <div className="space-y-3">
      <div>
        <h2 className="font-semibold">{block?.name ?? action.type}</h2>
        <p className="text-xs text-slate-500">
          {block?.description ?? "This block is not known for the chosen robot."}
        </p>
      </div>
      <Field label="Label" hint="A short name shown in the timeline and to the wizard.">
        {(p) => (
          <Input {...p} value={action.name} onChange={(e) => run(commands.renameAction(action.id, e.target.value))} />
        )}
      </Field>
      {action.type === "record_answer" ? (
        <>
          <AnswerEditor action={action} run={run} problems={problems} />
          <TimeLimitField
            draft={draft}
            stepId={step.id}
            limit={action.timeLimit}
            label="No answer in (seconds)"
            hint="Counted once the actions before this question are done. Leave empty to wait for the answer."
            onChange={(limit) => run(commands.setAnswerTimeLimit(action.id, limit))}
          />
        </>
      ) : action.type === "wait_for" ? (
        <WaitEditor draft={draft} stepId={step.id} action={action} events={robotEvents} run={run} />
      ) : action.type === "branch" ? (
        <BranchEditor draft={draft} action={action} answer={step.actions[index - 1]} run={run} />
      ) : action.type === "play_audio" ? (
        <AudioChooser studyId={studyId} action={action} player={audioPlayer} robotName={robotName} run={run} />
      ) : block ? (
        <SchemaForm
          schema={block.parameterSchema}
          value={action.parameters}
          onChange={setParameters}
          problems={problems}
        />
      ) : null}
      {block && !OWN_EDITORS.has(action.type) && (
        <VariantsField action={action} block={block} conditions={conditions} run={run} />
      )}
      {!WAITS_FOR_CHOICE.has(action.type) && !WAITS_FOR_CHOICE.has(step.actions[index - 1]?.type ?? "") && (
        <label className="flex items-center gap-2 text-sm">
          <input
            type="checkbox"
            className="h-4 w-4"
            disabled={index === 0}
            checked={Boolean(action.parallelGroup && step.actions[index - 1]?.parallelGroup === action.parallelGroup)}
            onChange={(e) => run(commands.setRunTogether(action.id, e.target.checked))}
          />
          Starts together with the action above
        </label>
      )}
      <Field
        label="Note for the wizard"
        hint="Shown to the wizard beside this action during the trial (what to watch for, when to go on). Not part of the methods text."
      >
        {(p) => (
          <Textarea
            {...p}
            rows={2}
            maxLength={2000}
            value={action.note ?? ""}
            onChange={(e) => run(commands.setNote(action.id, e.target.value))}
          />
        )}
      </Field>
      <IssueList issues={own.filter((i) => !i.parameter)} />
      <Toolbar what="action" onMove={onMove} onDelete={onDelete} />
    </div>
  );
}

type Option = { id: string; label: string };

function AnswerEditor({
  action,
  run,
  problems,
}: {
  action: DesignAction;
  run: Props["run"];
  problems: Array<{ parameter: string; message: string }>;
}) {
  const options = (Array.isArray(action.parameters.options) ? action.parameters.options : []) as Option[];
  const setOptions = (next: Option[]) => run(commands.setParameter(action.id, "options", next));
  const schema: ParameterSchema = {
    type: "object",
    properties: { prompt: { type: "string", title: "Question for the wizard" } },
  };
  return (
    <div className="space-y-3">
      <SchemaForm
        schema={schema}
        value={action.parameters}
        onChange={(v) => run(commands.setParameter(action.id, "prompt", v.prompt))}
        problems={problems}
      />
      <fieldset className="space-y-2">
        <legend className="text-sm font-medium text-slate-700">Answers the wizard can record</legend>
        {options.map((o, i) => (
          <div key={o.id} className="flex gap-1">
            <Input
              aria-label={`Answer ${i + 1}`}
              value={o.label}
              onChange={(e) => setOptions(options.map((x) => (x.id === o.id ? { ...x, label: e.target.value } : x)))}
            />
            <Button
              variant="ghost"
              size="sm"
              aria-label={`Remove answer ${i + 1}`}
              onClick={() => setOptions(options.filter((x) => x.id !== o.id))}
            >
              <X className="h-4 w-4" aria-hidden />
            </Button>
          </div>
        ))}
        {problems
          .filter((p) => p.parameter === "options")
          .map((p) => (
            <p key={p.message} className="text-sm text-red-600">
              {p.message}
            </p>
          ))}
        <Button
          variant="secondary"
          size="sm"
          onClick={() => setOptions([...options, { id: newId(), label: `Answer ${options.length + 1}` }])}
        >
          <Plus className="h-4 w-4" aria-hidden /> Add an answer
        </Button>
      </fieldset>
    </div>
  );
}

function BranchEditor({
  draft,
  action,
  answer,
  run,
}: {
  draft: DesignDraft;
  action: DesignAction;
  answer: DesignAction | undefined;
  run: Props["run"];
}) {
  if (answer?.type !== "record_answer") {
    return (
      <p className="text-sm text-amber-800">
        Place this branch right after a “Record answer” block: it goes where the recorded answer says.
      </p>
    );
  }
  const options = (Array.isArray(answer.parameters.options) ? answer.parameters.options : []) as Option[];
  const targets = (action.parameters.targets ?? {}) as Record<string, string>;
  return (
    <fieldset className="space-y-3">
      <legend className="text-sm font-medium text-slate-700">For each answer, go to</legend>
      {options.map((o) => (
        <div key={o.id} className="space-y-1">
          <Field
            label={`If “${o.label}”`}
            required
            error={targets[o.id] ? undefined : "Choose a step for this answer."}
          >
            {(p) => (
              <NativeSelect
                {...p}
                value={targets[o.id] ?? ""}
                onChange={(e) => run(commands.setBranchTarget(action.id, o.id, e.target.value || null))}
              >
                <option value="">Choose a step…</option>
                {draft.steps.map((s, i) => (
                  <option key={s.id} value={s.id}>
                    Step {i + 1}: {s.name}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
          {!targets[o.id] && (
            <Button
              variant="ghost"
              size="sm"
              onClick={() => run(commands.addStepForAnswer(action.id, o.id, `Response — ${o.label}`))}
            >
              <Plus className="h-4 w-4" aria-hidden /> Create a new step for “{o.label}”
            </Button>
          )}
        </div>
      ))}
    </fieldset>
  );
}

export function IssueList({ issues }: { issues: DesignIssue[] }) {
  if (!issues.length) return null;
  return (
    <ul className="space-y-1 text-sm">
      {issues.map((i, n) => (
        <li key={n} className={i.severity === "error" ? "text-red-700" : "text-amber-800"}>
          {i.message}
        </li>
      ))}
    </ul>
  );
}
