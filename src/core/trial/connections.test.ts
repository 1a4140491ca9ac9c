import { describe, expect, it } from "vitest";
import { type Connections, indicators } from "./connections";

const shown = (c: Connections) => indicators(c).map((i) => `${i.what} ${i.state} (${i.tone})`);

describe("what the wizard's page says of the runtime, the robot and the database", () => {
  it.each<[string, Connections, string[]]>([
    [
      "all well",
      { runtime: "live", robot: { connected: true }, database: "connected" },
      ["runtime live (green)", "robot connected (green)", "database connected (green)"],
    ],
    [
      "the runtime away: what it said of the robot no longer holds",
      { runtime: "reconnecting", robot: { connected: true }, database: "connected" },
      ["runtime reconnecting (red)", "robot unknown (slate)", "database connected (green)"],
    ],
    [
      "the database frozen, the runtime still live",
      { runtime: "live", robot: { connected: true }, database: "unavailable" },
      ["runtime live (green)", "robot connected (green)", "database unavailable (red)"],
    ],
    [
      "a robot that reported trouble while connected",
      { runtime: "live", robot: { connected: true, detail: "camera refused" }, database: "checking" },
      ["runtime live (green)", "robot connected (camera refused) (amber)", "database checking (slate)"],
    ],
    [
      "a robot gone",
      { runtime: "live", robot: { connected: false, detail: "no answer" }, database: "connected" },
      ["runtime live (green)", "robot disconnected (no answer) (red)", "database connected (green)"],
    ],
    [
      "the runtime connected but not answering (frozen): nothing it said still holds",
      { runtime: "silent", robot: { connected: true }, database: "connected" },
      ["runtime not answering (red)", "robot unknown (slate)", "database connected (green)"],
    ],
    [
      "the trial ended: its robot let go on purpose, no alarm",
      { runtime: "live", robot: { connected: false, detail: "closed" }, database: "connected", ended: true },
      ["runtime live (green)", "robot released (slate)", "database connected (green)"],
    ],
    [
      "no robot said yet",
      { runtime: "reconnecting", robot: null, database: "checking" },
      ["runtime reconnecting (red)", "database checking (slate)"],
    ],
  ])("%s", (_, connections, expected) => {
    expect(shown(connections)).toEqual(expected);
  });
});
