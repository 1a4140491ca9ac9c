// The ELAN export read back by pympi, the reference Python library for ELAN
// files: what a video coder's tools will see. pympi comes from the tests'
// own Python environment (tests/support/python.ts), never the machine's.
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { beforeAll, describe, expect, it } from "vitest";
import { elanDocument } from "../../src/core/analysis/elan";
import { schemeTemplate } from "../../src/core/coding/templates";
import { simulate, type Command, type TrialProtocol } from "../../src/core/trial";
import { storytellerDraft } from "../../src/server/seed/storyteller";
import { pythonEnvironment, runPython } from "../support/python";
import { scratchRoot } from "../support/scratch";

const protocol: TrialProtocol = storytellerDraft();
const done = (...ids: string[]): Command[] =>
  ids.flatMap(
    (actionId) =>
      [
        { kind: "dispatched", actionId },
        { kind: "completed", actionId },
      ] as Command[],
  );
const run: Command[] = [
  { kind: "start" },
  { kind: "next" },
  ...done("introduction-0", "introduction-1"),
  { kind: "next" },
  // The narrative gesture skipped by the wizard: a deviation.
  { kind: "skip", actionId: "story-1" },
  { kind: "next" },
  // Off script: its span on the Action tier runs from the wizard's request to the robot's completion.
  { kind: "unscripted", actionId: "bless", actionType: "say", parameters: { text: "Bless you" } },
  ...done("bless"),
  ...done("story-0"),
  { kind: "next" },
  { kind: "next" },
  ...done("recall-0"),
  { kind: "next" },
  ...done("recall-1"),
  { kind: "answer", actionId: "recall-2", optionId: "correct" },
  { kind: "next" },
  ...done("response-correct-0", "response-correct-1"),
  { kind: "next" },
];

describe("the ELAN export", () => {
  beforeAll(() => void pythonEnvironment(), 900_000);

  it("opens in pympi with the trial's steps, actions, answers, deviations and annotations on their times", () => {
    const log = simulate(protocol, run, (i) => i * 250).log;
    const eaf = elanDocument({
      protocol,
      events: log,
      annotations: [{ relMs: 1200, label: `She said "wow" <laughs> & smiles`, note: "" }],
      date: "2026-11-23T10:00:00Z",
    });
    const file = join(scratchRoot(), "storyteller.eaf");
    writeFileSync(file, eaf);
    const { tiers } = JSON.parse(runPython("read_eaf.py", [file])) as {
      tiers: Record<string, Array<[number, number, string]>>;
    };
    expect(Object.keys(tiers).sort()).toEqual(["Action", "Annotation", "Answer", "Deviation", "Step"]);
    expect(tiers.Step!.map((s) => s[2])).toEqual(["Introduction", "Story", "Recall question", "Response — correct"]);
    expect(tiers.Step!.every(([start, end]) => end > start)).toBe(true);
    expect(tiers.Action!.map((a) => a[2])).toContain("Question: What color was the rock Kai found?");
    expect(tiers.Deviation!.map((d) => d[2])).toEqual([
      "skipped: Look down at the crater",
      "unscripted: Say: Bless you",
    ]);
    // The answer's value, when the wizard recorded it: the question is on the Action tier at that moment.
    const recorded = log.find((e) => e.type === "answer.recorded")!.relMs!;
    expect(tiers.Answer).toEqual([[recorded, recorded + 1, "correct (red)"]]);
    expect(tiers["Annotation"]).toEqual([[1200, 2200, `She said "wow" <laughs> & smiles`]]);
    const at = (type: string) => log.find((e) => "actionId" in e && e.actionId === "bless" && e.type === type)!.relMs;
    expect(tiers.Action!.filter((a) => a[2].endsWith("(unscripted)"))).toEqual([
      [at("action.requested"), at("action.completed"), "Say: Bless you (unscripted)"],
    ]);
  });

  it("puts what the robot sensed on a Robot senses tier, with the robot's time and the message that matched", () => {
    const waiting: TrialProtocol = {
      steps: [
        {
          id: "ask",
          name: "Touch to start",
          actions: [
            {
              id: "wait",
              type: "wait_for",
              parameters: { events: [{ id: "t", event: "head_touched", after: { to: "end" } }] },
            },
          ],
        },
      ],
    };
    const at = Date.UTC(2026, 10, 23, 10, 0, 1, 250);
    const log = simulate(
      waiting,
      [
        { kind: "start" },
        { kind: "sensed", event: "left_hand_touched", at: at - 1000, message: { data: true } },
        { kind: "sensed", event: "head_touched", at, message: { data: true } },
      ],
      (i) => i * 250,
    ).log;
    const file = join(scratchRoot(), "touch.eaf");
    writeFileSync(
      file,
      elanDocument({ protocol: waiting, events: log, annotations: [], date: "2026-11-23T10:00:00Z" }),
    );
    const { tiers } = JSON.parse(runPython("read_eaf.py", [file])) as {
      tiers: Record<string, Array<[number, number, string]>>;
    };
    const sensedAt = log.filter((e) => e.type === "robot.sensed").map((e) => e.relMs!);
    expect(tiers["Robot senses"]).toEqual([
      [sensedAt[0], sensedAt[0]! + 1, `left_hand_touched (robot's time 2026-11-23T10:00:00.250Z): {"data":true}`],
      [sensedAt[1], sensedAt[1]! + 1, `head_touched (robot's time 2026-11-23T10:00:01.250Z): {"data":true}`],
    ]);
  });

  it("gives every observer a tier of their own per set of codes, states spanning their time", () => {
    const log = simulate(protocol, run, (i) => i * 250).log;
    const scheme = schemeTemplate("participant-engagement");
    const code = (
      observer: string,
      setId: string,
      codeId: string,
      startMs: number,
      endMs: number | null,
      modifiers: string[] = [],
    ) => ({
      trialId: "t1",
      observer,
      scheme,
      schemeVersion: 1,
      setId,
      codeId,
      kind: setId === "gaze" ? ("state" as const) : ("point" as const),
      startMs,
      endMs,
      modifiers,
    });
    const eaf = elanDocument({
      protocol,
      events: log,
      annotations: [],
      date: "2026-11-23T10:00:00Z",
      codes: [
        code("Ana", "gaze", "robot", 0, 2000),
        code("Ana", "gaze", "away", 2000, 3500),
        code("Ana", "expression", "smile", 1200, null, ["laugh"]),
        code("Ben", "gaze", "robot", 0, 2500),
        code("Ben", "gaze", "task", 2500, null),
      ],
    });
    const file = join(scratchRoot(), "storyteller-coded.eaf");
    writeFileSync(file, eaf);
    const { tiers } = JSON.parse(runPython("read_eaf.py", [file])) as {
      tiers: Record<string, Array<[number, number, string]>>;
    };
    expect(Object.keys(tiers).sort()).toEqual([
      "Action",
      "Ana - Expression",
      "Ana - Gaze",
      "Annotation",
      "Answer",
      "Ben - Gaze",
      "Deviation",
      "Step",
    ]);
    expect(tiers["Ana - Gaze"]).toEqual([
      [0, 2000, "At the robot"],
      [2000, 3500, "Away"],
    ]);
    expect(tiers["Ana - Expression"]).toEqual([[1200, 1201, "Smile (laugh)"]]);
    // A state still held when the trial ended lasts to the trial's last event.
    const lastMs = Math.max(...log.map((e) => e.relMs ?? 0));
    expect(tiers["Ben - Gaze"]).toEqual([
      [0, 2500, "At the robot"],
      [2500, lastMs, "At the task"],
    ]);
  });

  it("links the recording, with every time moved to where it falls in the recording", () => {
    const log = simulate(protocol, run, (i) => i * 250).log;
    const annotations = [{ relMs: 1200, label: "Look", note: "" }];
    const eaf = elanDocument({
      protocol,
      events: log,
      annotations,
      date: "2026-11-23T10:00:00Z",
      media: { fileName: "recording-r1.webm", mimeType: "video/webm;codecs=vp8", offsetMs: -1500 },
    });
    const file = join(scratchRoot(), "storyteller-recorded.eaf");
    writeFileSync(file, eaf);
    const { media, tiers } = JSON.parse(runPython("read_eaf.py", [file])) as {
      media: Array<Record<string, string>>;
      tiers: Record<string, Array<[number, number, string]>>;
    };
    const annotated = tiers.Annotation;
    expect(media).toEqual([
      expect.objectContaining({
        MEDIA_URL: "file:///recording-r1.webm",
        RELATIVE_MEDIA_URL: "./recording-r1.webm",
        MIME_TYPE: "video/webm",
      }),
    ]);
    // The recording began 1.5 s before t0: a moment 1.2 s into the trial is 2.7 s into the recording.
    expect(annotated).toEqual([[2700, 3700, "Look"]]);
  });
});
