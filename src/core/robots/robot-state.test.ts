import { describe, expect, it } from "vitest";
import { began, SAID_KEPT } from "./robot-state";

const at = new Date("2026-11-27T10:00:00Z");

describe("the lines the robot began to say", () => {
  it.each<[string, string[], string, string[]]>([
    ["the first", [], "Hello", ["Hello"]],
    ["the same line again is said again", ["Hello"], "Hello", ["Hello", "Hello"]],
    [
      "past the last kept, the oldest is let go",
      Array.from({ length: SAID_KEPT }, (_, i) => `line ${i}`),
      "new",
      [...Array.from({ length: SAID_KEPT - 1 }, (_, i) => `line ${i + 1}`), "new"],
    ],
  ])("%s", (_, before, text, after) => {
    const said = began(
      before.map((t) => ({ text: t, at: at.toISOString() })),
      text,
      at,
    );
    expect(said.map((s) => s.text)).toEqual(after);
    expect(said.at(-1)).toEqual({ text, at: "2026-11-27T10:00:00.000Z" });
  });
});
