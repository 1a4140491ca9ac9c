// A trial whose actions have no labels, as a newcomer builds one: its analysis
// and every export still name each action (by its block and main setting) and
// each step. Designed, published and exported through the real API on a real
// database; the wizard's run comes from the engine, stored through the event
// store; the ELAN file is read back by pympi, the reference ELAN library.
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { fidelityReport } from "../../src/core/analysis/fidelity";
import { type Command, type EngineEvent, simulate, type TrialEvent, type TrialProtocol } from "../../src/core/trial";
import { appendEvents, type TrialCursor } from "../../src/store/event-store";
import { buildFixture } from "../api/fixture";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { runPython } from "../support/python";
import { scratchRoot } from "../support/scratch";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

const STEPS = [
  {
    name: "Welcome",
    actions: [
      { type: "say", parameters: { text: "Hi! I am Nao, and today I will tell you a story." } },
      { type: "wave" },
      { type: "pause", parameters: { seconds: 3 } },
    ],
  },
  {
    name: "Quiz",
    actions: [
      {
        type: "record_answer",
        parameters: {
          prompt: "Which planet did Kai visit?",
          options: [
            { id: "mars", label: "Mars" },
            { id: "venus", label: "Venus" },
          ],
        },
      },
      { type: "posture", parameters: { posture: "sit" } },
      { type: "nao6-ros2.play_animation_bow" },
    ],
  },
  {
    name: "Goodbye",
    actions: [{ type: "wizard_instruction", parameters: { text: "Thank them." } }, { type: "end_trial" }],
  },
];

/** The wizard's run: next until the end, the robot finishing each action, the first answer, one gesture skipped and one nod off script. */
function wizardRun(protocol: TrialProtocol): EngineEvent[] {
  const commands: Command[] = [];
  const send = (command: Command) => {
    const { last } = simulate(protocol, [...commands, command]);
    if (typeof last !== "string") commands.push(command);
    return last;
  };
  const wave = protocol.steps[0]!.actions[1]!.id;
  const question = protocol.steps[1]!.actions[0]!.id;
  send({ kind: "start" });
  send({ kind: "unscripted", actionId: "off-script-nod", actionType: "nod", parameters: {} });
  send({ kind: "completed", actionId: "off-script-nod" });
  send({ kind: "skip", actionId: wave });
  for (let i = 0; i < 50; i++) {
    const last = send({ kind: "next" });
    if (typeof last === "string") {
      expect(last).toMatch(/Record the participant's answer/);
      send({ kind: "answer", actionId: question, optionId: "mars" });
      continue;
    }
    for (const e of last)
      if (e.type === "action.requested" && !["wizard_instruction", "end_trial"].includes(e.actionType)) {
        send({ kind: "dispatched", actionId: e.actionId });
        send({ kind: "completed", actionId: e.actionId });
      }
    if (last.some((e) => e.type === "trial.completed")) break;
  }
  return simulate(protocol, commands).log.map(({ seq: _seq, relMs: _relMs, ...event }) => event as EngineEvent);
}

describe("a trial whose actions have no labels", () => {
  let trialId = "";
  let protocol: TrialProtocol;
  beforeAll(async () => {
    const study = await f.newStudy();
    const experiment = await owner.experiments.create({ studyId: study.id, name: "Quiz", robotId: "nao6-ros2" });
    await owner.experiments.saveDesign({ experimentId: experiment.id, baseRevision: 0, steps: STEPS });
    const version = await owner.versions.publish({ experimentId: experiment.id });
    trialId = (await owner.trials.create({ versionId: version.id })).id;
    protocol = (await owner.trials.get({ trialId })).protocol as TrialProtocol;
    expect(protocol.steps.flatMap((s) => s.actions).every((a) => !a.name)).toBe(true);
    // Stored one event at a time, 250 ms apart, as the runtime would have.
    const start = Date.parse("2026-11-23T10:00:00Z");
    const cursor: TrialCursor = { id: trialId, lastSeq: 0, t0: null };
    for (const [i, event] of wizardRun(protocol).entries()) {
      const at = new Date(start + i * 250);
      await appendEvents(db, cursor, [event], f.people.owner.id, { now: () => at });
      cursor.lastSeq++;
      cursor.t0 ??= at;
    }
  });

  const ACTIONS = [
    "Say: Hi! I am Nao, and today I will…",
    "Wave",
    "Pause 3 s",
    "Record answer: Which planet did Kai visit?",
    "Posture: Sit",
    "Bow",
    "Wizard instruction: Thank them.",
    "End trial",
  ];

  it("names every planned action in the analysis, the robot's own actions as its plugin does", async () => {
    const trial = await owner.trials.get({ trialId });
    const events = await owner.trials.events({ trialId });
    const report = fidelityReport(
      trial.protocol as TrialProtocol,
      events as unknown as TrialEvent[],
      trial.actionNames,
    );
    expect(report.actions.map((a) => a.name)).toEqual(ACTIONS);
    expect(report.actions.map((a) => a.outcome)).toEqual([
      "executed",
      "skipped",
      "executed",
      "executed",
      "executed",
      "executed",
      "executed",
      "executed",
    ]);
    expect(report.unscripted.map((u) => u.name)).toEqual(["Nod"]);
  });

  it("names the step and the action of every row of the events CSV", async () => {
    const [header, ...rows] = parseCsv(
      await new Response((await owner.trials.export({ trialId, format: "csv" })).body).text(),
    );
    const column = (name: string) => header!.indexOf(name);
    const about = rows.filter((r) => r[column("action_id")] || r[column("step_id")]);
    expect(about.length).toBeGreaterThan(20);
    for (const row of about) {
      if (row[column("action_id")]) expect(row[column("action_name")], row.join(" | ")).not.toBe("");
      if (row[column("step_id")]) expect(row[column("step_name")], row.join(" | ")).not.toBe("");
    }
    const requested = rows.filter((r) => r[column("type")] === "action.requested").map((r) => r[column("action_name")]);
    expect(requested).toEqual(["Nod", ...ACTIONS.filter((a) => a !== "Wave" && !a.startsWith("Record answer"))]);
    expect(rows.filter((r) => r[column("type")] === "step.entered").map((r) => r[column("step_name")])).toEqual([
      "Welcome",
      "Quiz",
      "Goodbye",
    ]);
  });

  it("names them in the trial record (JSON)", async () => {
    const record = JSON.parse(
      await new Response((await owner.trials.export({ trialId, format: "json" })).body).text(),
    ) as {
      events: Array<{ type: string; actionId?: string; stepId?: string; actionName?: string; stepName?: string }>;
    };
    for (const e of record.events) {
      if (e.actionId) expect(e.actionName, JSON.stringify(e)).toMatch(/\w/);
      if (e.stepId) expect(e.stepName, JSON.stringify(e)).toMatch(/\w/);
    }
    expect(record.events.find((e) => e.type === "answer.recorded")).toMatchObject({
      stepName: "Quiz",
      actionName: "Record answer: Which planet did Kai visit?",
    });
    expect(record.events.find((e) => e.type === "action.skipped")).toMatchObject({ actionName: "Wave" });
  });

  it("names every action, step and deviation in the ELAN file, as pympi reads it", async () => {
    const file = join(scratchRoot(), `unlabelled-${trialId}.eaf`);
    writeFileSync(file, (await owner.trials.export({ trialId, format: "eaf" })).body as string);
    const { tiers } = JSON.parse(runPython("read_eaf.py", [file])) as {
      tiers: Record<string, Array<[number, number, string]>>;
    };
    expect(tiers.Step!.map((s) => s[2])).toEqual(["Welcome", "Quiz", "Goodbye"]);
    // Speech and instructions in full, for the coder; the skipped wave was never performed.
    expect(tiers.Action!.map((a) => a[2])).toEqual([
      "Nod (unscripted)",
      "Say: Hi! I am Nao, and today I will tell you a story.",
      "Pause 3 s",
      "Record answer: Which planet did Kai visit?",
      "Posture: Sit",
      "Bow",
      "Wizard instruction: Thank them.",
      "End trial",
    ]);
    expect(tiers.Deviation!.map((d) => d[2])).toEqual(["unscripted: Nod", "skipped: Wave"]);
    // The first run on a machine installs pympi into the tests' Python environment.
  }, 900_000);
});
