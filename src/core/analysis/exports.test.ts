import { describe, expect, it } from "vitest";
import { parseCsv } from "../../../tests/support/csv";
import type { StoredEvent } from "@/core/trial";
import { csvLines } from "@/core/csv/csv";
import {
  EVENT_COLUMNS,
  eventRows,
  eventsCsv,
  jsonPieces,
  namedEvents,
  samplesCsv,
  trialRecordJson,
  trialRecordPieces,
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

/** The wizard recording the participant's answer: its label has a comma, so the cell is quoted. */
const answered: StoredEvent = {
  seq: 3,
  type: "answer.recorded",
  relMs: 40,
  trialId: "t1",
  serverTime: new Date("2026-01-01T10:00:00.040Z"),
  actorId: "u1",
  stepId: "s1",
  actionId: "q1",
  optionId: "mars",
  label: "Mars, the red one",
};

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
      "variant",
      "answer",
      "sensed",
      "deviation",
      "rel_ms",
      "server_time",
      "actor_id",
      "payload",
    ]);
    expect(rows.map((r) => JSON.parse(r[17]!))).toEqual(JSON.parse(JSON.stringify(events)));
    expect(rows[1]!.slice(0, 17)).toEqual([
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
      "",
      "",
      "",
      "unscripted",
      "12.5",
      "2026-01-01T10:00:00.012Z",
      "u1",
    ]);
  });

  it("names the condition whose variant of an action ran, in its own column and on the record's events", () => {
    const scripted = { ...events[1]!, scripted: true, deviation: undefined } as StoredEvent;
    const varied = trialNames(
      {
        steps: [
          {
            id: "s1",
            name: "Welcome",
            actions: [{ id: "a1", type: "say", parameters: { text: "Hello, friend" }, variant: "Warm tutor" }],
          },
        ],
      },
      [scripted],
    );
    const [, row] = parseCsv(eventsCsv("t1", [scripted], people, varied));
    expect(row![EVENT_COLUMNS.indexOf("variant")]).toBe("Warm tutor");
    expect(namedEvents([scripted], varied)[0]).toMatchObject({ actionId: "a1", variant: "Warm tutor" });
  });
});

describe("the events CSV's answer column", () => {
  it.each([
    ["a recorded answer: its label", 2, "Mars, the red one"],
    ["any other event: empty", 0, ""],
  ])("%s", (_, row, answer) => {
    const [header, ...rows] = parseCsv(eventsCsv("t1", [...events, answered], people, names));
    expect(rows[row]![header!.indexOf("answer")]).toBe(answer);
  });
});

/** The robot sensing its head touched: its time and message stay in the payload. */
const sensed: StoredEvent = {
  seq: 4,
  type: "robot.sensed",
  relMs: 55,
  trialId: "t1",
  serverTime: new Date("2026-01-01T10:00:00.055Z"),
  actorId: null,
  event: "head_touched",
  at: 1_767_261_600_050,
  message: { button: 2, state: 1 },
};

describe("the events CSV's sensed column", () => {
  it.each([
    ["what the robot sensed: its event's id", 3, "head_touched"],
    ["a recorded answer: empty", 2, ""],
    ["any other event: empty", 1, ""],
  ])("%s", (_, row, event) => {
    const [header, ...rows] = parseCsv(eventsCsv("t1", [...events, answered, sensed], people, names));
    expect(rows[row]![header!.indexOf("sensed")]).toBe(event);
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
          protocol: { schemaVersion: 5, experiment: {} as never, steps: [] },
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

describe("the trial record and events CSV written a batch at a time", () => {
  const record = {
    trial: { id: "t1", note: 'a "quoted"\n  "events": [] line', gone: undefined, at: new Date(0) },
    protocol: {
      schemaVersion: 5 as const,
      experiment: {} as never,
      steps: [{ id: "s1", name: "Welcome", description: "", actions: [] }],
    },
    annotations: [
      { relMs: 5, label: "Looks away", note: "", authorName: null },
      { relMs: 5, label: "Laughs\n", note: 'said "no"', authorName: "Olga" },
      { relMs: 9, label: "Waves", note: "🪨", authorName: null },
    ],
    questionnaires: [{ questionnaire: "Godspeed", answers: { q1: 4, q2: [1, 2] }, score: null, at: new Date(0) }],
    recordings: [{ nested: { deeper: [1, [2, {}], []] } }],
    samples: [
      { topic: "/joint_states", relMs: 1, data: { position: [0.5] } },
      { topic: "/battery_state", relMs: 1, data: { percentage: 0.8, empty: {}, none: [] } },
      { topic: "/joint_states", relMs: 2, data: { position: [-0.25] } },
    ],
    codes: [{ trial_id: "t1", code: "Gaze", end_ms: null }],
  };
  const many = Array.from({ length: 7 }, (_, i) => ({ ...events[i % 2]!, seq: i + 1 }));
  /** `all` in batches of the sizes given, as a paged read gives them. */
  async function* batches<T>(all: readonly T[], sizes: readonly number[]) {
    let at = 0;
    for (const size of sizes) yield all.slice(at, (at += size));
  }
  it.each([
    ["no events, every list in one batch", [], [], [3]],
    ["one page of events, no samples", events, [2], []],
    ["pages of one, three and three; lists in batches of one and two", many as StoredEvent[], [1, 3, 3], [1, 2]],
    ["empty batches among the rest", many as StoredEvent[], [0, 7, 0], [0, 3, 0]],
  ] as const)("%s: the same bytes as the whole record and the whole CSV", async (_, all, pages, sizes) => {
    // A list split as `sizes` asks, its last items in one more batch.
    const split = <T>(list: readonly T[]) => batches(list, [...sizes, list.length]);
    const streamed = trialRecordPieces({
      ...record,
      events: batches(namedEvents([...all], names), pages),
      annotations: split(record.annotations),
      questionnaires: split(record.questionnaires),
      samples: sizes.length ? split(record.samples) : [],
      codes: split(record.codes),
    });
    let json = "";
    for await (const piece of streamed) json += piece;
    let csv = csvLines([EVENT_COLUMNS]);
    for await (const page of batches(all, pages)) csv += csvLines(eventRows("t1", page, people, names));
    const samples = sizes.length ? record.samples : [];
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
        samples,
        codes: record.codes,
      },
      null,
      2,
    );
    expect(json).toBe(expected);
    expect(trialRecordJson({ ...record, samples, events: [...all] }, names)).toBe(expected);
    expect(csv).toBe(eventsCsv("t1", [...all], people, names));
  });

  it.each([
    ["an empty object", {}],
    ["values JSON leaves out", { a: undefined, b: () => 1, c: 1 }],
    ["a top-level string with a newline", { a: "x\ny", b: [] }],
  ])("writes %s as JSON.stringify does", async (_, object) => {
    let json = "";
    for await (const piece of jsonPieces(object)) json += piece;
    expect(json).toBe(JSON.stringify(object, null, 2));
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
