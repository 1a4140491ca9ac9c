import { describe, expect, it } from "vitest";
import { areTheseEvents } from "./landed";
import type { EngineEvent, StoredEvent } from "./types";

const stored = (event: EngineEvent, seq: number): StoredEvent => ({
  ...event,
  seq,
  relMs: 10,
  trialId: "t",
  serverTime: new Date(0),
  actorId: "w",
});
const say: EngineEvent = {
  type: "action.requested",
  stepId: "s",
  actionId: "a",
  actionType: "say",
  parameters: { text: "Hello", speed: 1 },
  scripted: true,
};
// As the database gives JSON back: keys in another order.
const sayReordered = JSON.parse(
  '{"scripted":true,"parameters":{"speed":1,"text":"Hello"},"actionType":"say","actionId":"a","stepId":"s","type":"action.requested"}',
) as EngineEvent;
const note: EngineEvent = { type: "note.added", text: "Participant smiled" };

describe("areTheseEvents", () => {
  it.each([
    ["the same events, as stored", [stored(say, 4)], [say], true],
    ["the same events, keys in the database's order", [stored(sayReordered, 4)], [say], true],
    ["an earlier command's note where this one's speech was", [stored(note, 4)], [say], false],
    ["another text", [stored({ ...note, text: "Participant left" }, 4)], [note], false],
    ["fewer events than decided", [stored(say, 4)], [say, note], false],
    ["more events than decided", [stored(say, 4), stored(note, 5)], [say], false],
    ["a deviation the decision did not carry", [stored({ ...note, deviation: "unscripted" }, 4)], [note], false],
    ["nothing landed", [], [note], false],
  ])("%s", (_, landed, decided, same) => {
    expect(areTheseEvents(landed, decided)).toBe(same);
  });
});
