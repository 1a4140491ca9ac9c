import { describe, expect, it } from "vitest";
import { parseCsv } from "../../../tests/support/csv";
import type { StoredEvent } from "@/core/trial";
import { csvLines } from "@/core/csv/csv";
import {
  EVENT_COLUMNS,
  eventRows,
  eventsCsv,
  jsonArrayWriter,
  namedEvents,
  samplesCsv,
  trialRecordFrame,
  trialRecordJson,
} from "./exports";
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

const names = trialNames({ steps: [{ id: "s1", name: "Welcome", description: "", actions: [] }] }, events);
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

describe("the trial record and events CSV written a page of events at a time", () => {
  const record = {
    trial: { id: "t1", note: 'a "quoted"\n  "events": [] line', gone: undefined, at: new Date(0) },
    protocol: {
      schemaVersion: 2 as const,
      experiment: {} as never,
      steps: [{ id: "s1", name: "Welcome", description: "", actions: [] }],
    },
    annotations: [{ relMs: 5, label: "Looks away", note: "", authorName: null }],
    questionnaires: [],
    recordings: [{ nested: { deeper: [1, [2, {}], []] } }],
    samples: [{ topic: "/joint_states", relMs: 1, data: { position: [0.5] } }],
    codes: [],
  };
  const many = Array.from({ length: 7 }, (_, i) => ({ ...events[i % 2]!, seq: i + 1 }));
  it.each([
    ["no events", [], []],
    ["one page", events, [2]],
    ["pages of one, three and three", many as StoredEvent[], [1, 3, 3]],
  ] as const)("%s: the same bytes as the whole record and the whole CSV", (_, all, pages) => {
    const frame = trialRecordFrame(record);
    const array = jsonArrayWriter(1);
    let json = frame.before;
    let csv = csvLines([EVENT_COLUMNS]);
    let at = 0;
    for (const size of pages) {
      const page = all.slice(at, (at += size));
      json += array.items(namedEvents(page, names));
      csv += csvLines(eventRows("t1", page, people, names));
    }
    json += array.end() + frame.after;
    // What the paged writer must match: the whole record in one JSON.stringify, events after the protocol.
    const expected = JSON.stringify(
      {
        schemaVersion: 3,
        trial: record.trial,
        protocol: record.protocol,
        events: namedEvents([...all], names),
        annotations: record.annotations,
        questionnaires: record.questionnaires,
        recordings: record.recordings,
        samples: record.samples,
        codes: record.codes,
      },
      null,
      2,
    );
    expect(json).toBe(expected);
    expect(trialRecordJson({ ...record, events: [...all] }, names)).toBe(expected);
    expect(csv).toBe(eventsCsv("t1", [...all], people, names));
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
