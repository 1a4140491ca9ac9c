import { describe, expect, it } from "vitest";
import { parseCsv } from "../../../tests/support/csv";
import type { StoredEvent } from "@/core/trial";
import { eventsCsv } from "./exports";

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

describe("the events CSV", () => {
  it("parses back to the same events, quotes, commas, newlines and all", () => {
    const [header, ...rows] = parseCsv(eventsCsv("t1", events, { wizard: "Wim Wizard", createdBy: "Rita Researcher" }));
    expect(header).toEqual([
      "trial_id",
      "wizard",
      "created_by",
      "seq",
      "type",
      "step_id",
      "action_id",
      "action_type",
      "deviation",
      "rel_ms",
      "server_time",
      "actor_id",
      "payload",
    ]);
    expect(rows.map((r) => JSON.parse(r[12]!))).toEqual(JSON.parse(JSON.stringify(events)));
    expect(rows[1]!.slice(0, 12)).toEqual([
      "t1",
      "Wim Wizard",
      "Rita Researcher",
      "2",
      "action.requested",
      "s1",
      "a1",
      "say",
      "unscripted",
      "12.5",
      "2026-01-01T10:00:00.012Z",
      "u1",
    ]);
  });
});

describe("the events CSV of a trial nobody ran yet", () => {
  it("leaves the wizard empty and still names who created it", () => {
    const [, row] = parseCsv(eventsCsv("t1", events.slice(0, 1), { wizard: null, createdBy: "Rita Researcher" }));
    expect(row!.slice(0, 3)).toEqual(["t1", "", "Rita Researcher"]);
  });
});
