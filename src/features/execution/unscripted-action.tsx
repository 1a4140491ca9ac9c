"use client";
// Any robot action off script, with its settings as a form. It runs at once
// and is recorded as an unscripted deviation.
import { useState } from "react";
import { ABSTRACT_ACTIONS, validateParameters, type ParameterProblem } from "@/core/plugins";
import type { WizardCommand } from "@/core/socket/messages";
import { Button } from "@/ui/button";
import { Field, NativeSelect } from "@/ui/field";
import { SchemaForm } from "@/ui/schema-form";

// A sound is chosen from the study's files in the designer; a form of its id and hash is no way to pick one live.
const ROBOT_ACTIONS = ABSTRACT_ACTIONS.filter((a) => !a.runtime && a.id !== "say" && a.id !== "play_audio");

export function UnscriptedAction({
  send,
  disabled,
}: {
  send: (c: WizardCommand) => Promise<{ ok: boolean }>;
  disabled: boolean;
}) {
  const [id, setId] = useState(ROBOT_ACTIONS[0]!.id);
  const [values, setValues] = useState<Record<string, unknown>>({});
  const [problems, setProblems] = useState<ParameterProblem[]>([]);
  const action = ROBOT_ACTIONS.find((a) => a.id === id)!;
  const submit = async () => {
    const parameters = Object.fromEntries(Object.entries(values).filter(([, v]) => v !== undefined && v !== ""));
    const found = validateParameters(action.parameterSchema, parameters);
    setProblems(found);
    if (found.length) return;
    if ((await send({ kind: "unscripted", actionType: id, parameters })).ok) setValues({});
  };
  return (
    <details className="rounded-lg border border-slate-200 bg-white p-3">
      <summary className="cursor-pointer text-sm font-medium pointer-coarse:py-3">Unscripted robot action</summary>
      <div className="mt-3 space-y-3">
        <Field label="Action">
          {(a) => (
            <NativeSelect
              {...a}
              value={id}
              onChange={(e) => {
                setId(e.target.value);
                setValues({});
                setProblems([]);
              }}
            >
              {ROBOT_ACTIONS.map((x) => (
                <option key={x.id} value={x.id}>
                  {x.name}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <SchemaForm schema={action.parameterSchema} value={values} onChange={setValues} problems={problems} />
        <Button variant="secondary" disabled={disabled} onClick={() => void submit()}>
          Send “{action.name}” to the robot
        </Button>
      </div>
    </details>
  );
}
