import { describe, expect, it } from "vitest";
import { parseCsv } from "../../../tests/support/csv";
import type { StoredEvent } from "@/core/trial";
import { eventsCsv, samplesCsv, trialRecordJson } from "./exports";
import { trialNames } from "./names";

const events: StoredEvent[] = [
  {
    seq: 1,
    type: "trial.started",
    relMs: 0,
    trialId: "t1",
    serverTime: new Date("2026-01-01T10:00:00.000Z"),
    actorId: "u1",
  },
  {
    seq: 2,
    type: "action.requested",
    relMs: 12.5,
    trialId: "t1",
    serverTime: new Date("2026-01-01T10:00:00.012Z"),
    actorId: "u1",
    stepId: "s1",
    actionId: "a1",
    actionType: "say",
    parameters: { text: 'She said "hi", then\r\nleft; {{x}} 🪨' },
    scripted: false,
    deviation: "unscripted",
  },
];

const names = trialNames({ steps: [{ id: "s1", name: "Welcome", actions: [] }] }, events);
const people = { wizard: "Wim Wizard", createdBy: "Rita Researcher" };

describe("the events CSV", () => {
  it("parses back to the same events, quotes, commas, newlines and all", () => {
    const [header, ...rows] = parseCsv(eventsCsv("t1", events, people, names));
    expect(header).toEqual([
      "trial_id",
      "wizard",
      "created_by",
      "seq",
      "type",
      "step_id",
      "action_id",
      "action_type",
      "step_name",
      "action_name",
      "deviation",
      "rel_ms",
      "server_time",
      "actor_id",
      "payload",
    ]);
    expect(rows.map((r) => JSON.parse(r[14]!))).toEqual(JSON.parse(JSON.stringify(events)));
    expect(rows[1]!.slice(0, 14)).toEqual([
      "t1",
      "Wim Wizard",
      "Rita Researcher",
      "2",
      "action.requested",
      "s1",
      "a1",
      "say",
      "Welcome",
      'Say: She said "hi", then left; {{x}}…',
      "unscripted",
      "12.5",
      "2026-01-01T10:00:00.012Z",
      "u1",
    ]);
  });
});

describe("the events CSV of a trial nobody ran yet", () => {
  it("leaves the wizard empty and still names who created it", () => {
    const [, row] = parseCsv(
      eventsCsv("t1", events.slice(0, 1), { wizard: null, createdBy: "Rita Researcher" }, names),
    );
    expect(row!.slice(0, 3)).toEqual(["t1", "", "Rita Researcher"]);
  });
});

describe("the trial record", () => {
  it("names the step and the action each event is about", () => {
    const record = JSON.parse(
      trialRecordJson(
        {
          trial: {},
          protocol: { schemaVersion: 2, experiment: {} as never, steps: [] },
          events,
          annotations: [],
          codes: [],
          questionnaires: [],
          recordings: [],
          samples: [],
        },
        names,
      ),
    ) as { events: Array<Record<string, unknown>> };
    expect(record.events.map(({ stepName, actionName }) => ({ stepName, actionName }))).toEqual([
      { stepName: undefined, actionName: undefined },
      { stepName: "Welcome", actionName: 'Say: She said "hi", then left; {{x}}…' },
    ]);
  });
});

describe("the robot state samples CSV", () => {
  it("parses back to the samples: one row each, the message as JSON, quotes and commas included", () => {
    const samples = [
      { topic: "/joint_states", relMs: 0, data: { name: ["HeadYaw", "HeadPitch"], position: [0.1, -0.25] } },
      { topic: "/battery_state", relMs: 20.5, data: { percentage: 0.8, location: 'pack "A", left' } },
    ];
    const [header, ...rows] = parseCsv(samplesCsv("t1", samples)).filter((r) => r.length > 1);
    expect(header).toEqual(["trial_id", "topic", "rel_ms", "data"]);
    expect(
      rows.map(([trialId, topic, relMs, data]) => ({ trialId, topic, relMs: Number(relMs), data: JSON.parse(data!) })),
    ).toEqual(samples.map((s) => ({ trialId: "t1", ...s })));
  });
});
