import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import { snapshotOf } from "../protocol/snapshot";
import type { DesignDraft } from "./types";
import { unchangedSince } from "./published";

const published = storytellerDraft();
const latest = { version: 3, snapshot: snapshotOf({ ...published, id: "e1" }) };

/** The draft as the database gives it back: every object's keys in another order. */
function reordered<T>(value: T): T {
  if (Array.isArray(value)) return value.map(reordered) as T;
  if (!value || typeof value !== "object") return value;
  return Object.fromEntries(
    Object.entries(value)
      .reverse()
      .map(([k, v]) => [k, reordered(v)]),
  ) as T;
}

function edited(change: (d: DesignDraft) => void): DesignDraft {
  const draft = structuredClone(published);
  change(draft);
  return draft;
}

describe("is the draft what was last published?", () => {
  it.each<[string, DesignDraft, number | null, typeof latest | null]>([
    ["the same draft", structuredClone(published), 3, latest],
    ["the same draft, its keys in another order", reordered(published), 3, latest],
    ["never published", structuredClone(published), null, null],
    ["a step renamed", edited((d) => void (d.steps[0]!.name = "Hello")), null, latest],
    ["a parameter changed", edited((d) => void (d.steps[0]!.actions[0]!.parameters.text = "Hi")), null, latest],
    ["two actions swapped", edited((d) => void d.steps[0]!.actions.reverse()), null, latest],
    [
      "run together undone",
      edited((d) => d.steps[0]!.actions.forEach((a) => void (a.parallelGroup = null))),
      null,
      latest,
    ],
    [
      "a step added",
      edited((d) => void d.steps.push({ id: "new", name: "More", description: "", actions: [] })),
      null,
      latest,
    ],
    ["the experiment renamed", edited((d) => void (d.name = "Another")), null, latest],
  ])("%s", (_, draft, expected, version) => {
    expect(unchangedSince(draft, version)).toBe(expected);
  });

  const pinned = { ...latest, pluginHash: "a".repeat(64) };
  it.each<[string, typeof pinned | typeof latest, string | undefined, number | null]>([
    ["the same draft on the same plugin document", pinned, "a".repeat(64), 3],
    ["the same draft on another document (another source chosen, or a newer sync)", pinned, "b".repeat(64), null],
    ["the same draft, the document it runs not known yet", pinned, undefined, 3],
    ["the same draft, the version from before pinning", latest, "b".repeat(64), 3],
  ])("%s", (_, version, pluginHash, expected) => {
    expect(unchangedSince(structuredClone(published), version, pluginHash)).toBe(expected);
  });
});
