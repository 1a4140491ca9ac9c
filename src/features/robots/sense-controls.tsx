"use client";
// Making the simulated robot sense something, so a study that waits for a
// touch, a word or someone close is piloted without hardware: a button per
// touch sensor, a phrase it hears with a confidence, and a step close or away
// per distance sensor. The robot says what it can sense (SENSABLE_TOPIC); each
// control sends a Stimulus, and the robot publishes what its sensor would.
import { type FormEvent, useEffect, useMemo, useState } from "react";
import * as ROSLIB from "roslib";
import { type Sensable, SENSABLE_TOPIC, type Stimulus, STIMULUS_TOPIC } from "@/core/robots/stimulus";
import { Button } from "@/ui/button";
import { Field, Input } from "@/ui/field";

export function SenseControls({ ros }: { ros: ROSLIB.Ros | null }) {
  const [sensable, setSensable] = useState<Sensable[]>([]);
  const [close, setClose] = useState<Set<string>>(new Set());
  const [phrase, setPhrase] = useState("");
  const [confidence, setConfidence] = useState("0.8");
  const [sent, setSent] = useState("");
  // One publisher for the connection: roslib advertises a topic once per Topic.
  const control = useMemo(
    () => ros && new ROSLIB.Topic({ ros, name: STIMULUS_TOPIC, messageType: "std_msgs/msg/String" }),
    [ros],
  );

  useEffect(() => {
    if (!ros) return;
    const topic = new ROSLIB.Topic({ ros, name: SENSABLE_TOPIC, messageType: "std_msgs/msg/String" });
    topic.subscribe((message) => setSensable(JSON.parse((message as { data: string }).data) as Sensable[]));
    return () => topic.unsubscribe();
  }, [ros]);

  if (!control || !sensable.length) return null;
  const send = (stimulus: Stimulus, said: string) => {
    control.publish({ data: JSON.stringify(stimulus) });
    setSent(said);
  };
  const touches = sensable.filter((s) => s.kind === "pressed");
  const hearing = sensable.find((s) => s.kind === "heard");
  const distances = sensable.filter((s) => s.kind === "near");
  const hear = (event: FormEvent) => {
    event.preventDefault();
    const text = phrase.trim();
    const level = Number(confidence);
    if (!hearing || !text || !(level >= 0 && level <= 1)) return;
    send({ event: hearing.id, heard: text, confidence: level }, `Heard “${text}” (confidence ${level})`);
  };

  return (
    <section aria-label="What the robot senses" className="w-full max-w-xl space-y-4 text-sm">
      <h2 className="font-semibold">Make the robot sense</h2>
      {touches.length > 0 && (
        <div className="flex flex-wrap gap-2">
          {touches.map((t) => (
            <Button key={t.id} variant="secondary" size="sm" onClick={() => send({ event: t.id, touch: true }, t.name)}>
              {t.name}
            </Button>
          ))}
        </div>
      )}
      {hearing && (
        <form onSubmit={hear} className="flex flex-wrap items-end gap-2">
          <div className="min-w-48 flex-1">
            <Field label="A phrase the robot hears">
              {(props) => <Input {...props} value={phrase} onChange={(e) => setPhrase(e.target.value)} />}
            </Field>
          </div>
          <div className="w-36">
            <Field label="Confidence (0–1)">
              {(props) => (
                <Input
                  {...props}
                  type="number"
                  min={0}
                  max={1}
                  step={0.05}
                  value={confidence}
                  onChange={(e) => setConfidence(e.target.value)}
                />
              )}
            </Field>
          </div>
          <Button type="submit" size="sm" variant="secondary">
            Hear it
          </Button>
        </form>
      )}
      {distances.length > 0 && (
        <div className="flex flex-wrap gap-2">
          {distances.map((d) => {
            const near = close.has(d.id);
            return (
              <Button
                key={d.id}
                variant="secondary"
                size="sm"
                onClick={() => {
                  const next = new Set(close);
                  if (near) next.delete(d.id);
                  else next.add(d.id);
                  setClose(next);
                  send({ event: d.id, near: !near }, near ? `Stepped away: ${d.name}` : `Stepped close: ${d.name}`);
                }}
              >
                {near ? `Step away (${d.name})` : `Step close (${d.name})`}
              </Button>
            );
          })}
        </div>
      )}
      <p role="status" aria-label="Last sensed" className="min-h-5 text-slate-600">
        {sent && `Sent: ${sent}`}
      </p>
    </section>
  );
}
