// Every action of every first-party plugin, sent to the simulated robot
// through the runtime's robot link: what the dispatched event records as sent
// is, byte for byte, what the robot received (each topic message's JSON text,
// each SSH command line). Then those events, kept in the trial's log, come out
// unchanged in the events CSV, the trial JSON and the MCAP's robot-commands
// channel.
import { readdirSync, readFileSync } from "node:fs";
import { McapIndexedReader } from "@mcap/core";
import { afterAll, describe, expect, it } from "vitest";
import { loadPlugin, robotActionType, withDefaults, type Plugin, type Sent } from "../../src/core/plugins";
import { pluginRobot } from "../../src/runtime/robot-link";
import type { RobotReport } from "../../src/runtime/robot";
import { simulatedRobot, startSimulator } from "../../src/robots/simulator";
import { transportFor } from "../../src/robots/transports";
import { appendEvents } from "../../src/store/event-store";
import { buildFixture, publishedVersion } from "../api/fixture";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";

const PASSWORD = "simulated-nao";
// Text a paper quotes: quotes, a backslash, a line break and characters beyond ASCII.
const TEXT = 'She said "hello" \\ then\nça va? 🤖 赤い';
const FILLED: Record<string, string> = { text: TEXT, name: "animations/Stand/Gestures/Hey_1", sha256: "a".repeat(64) };

const plugins = readdirSync("plugins")
  .filter((file) => file.endsWith(".json") && file !== "plugin.schema.json")
  .map((file) => (loadPlugin(file, readFileSync(`plugins/${file}`, "utf8")) as { value: Plugin }).value);

/** Each required parameter as a researcher fills it: the first choice of a list, or text. */
function parametersOf(action: Plugin["actions"][number]) {
  const properties = action.parameterSchema.properties as Record<string, { enum?: unknown[] }>;
  const required = action.parameterSchema.required ?? [];
  return withDefaults(
    action.parameterSchema,
    Object.fromEntries(required.map((key) => [key, properties[key]?.enum?.[0] ?? FILLED[key] ?? "x"])),
  );
}

/** What a record of what was sent says reached the robot, one line per message, in order. */
const expectedOnWire = (sent: Sent | undefined): string[] => {
  if (!sent) return [];
  if (sent.via === "topic")
    return [`${sent.topic} ${sent.message}`, ...(sent.stop ? [`${sent.topic} ${sent.stop}`] : [])];
  if (sent.via === "service") return [`${sent.service} ${sent.args}`];
  if (sent.via === "action") return [`${sent.action} ${sent.goal}`];
  if (sent.via === "ssh") return [`ssh ${sent.command}`];
  return [`${sent.method} ${sent.url} ${sent.body ?? ""}`];
};

const dispatched: Array<{ actionId: string; detail: Record<string, unknown> }> = [];

describe.each(plugins.map((p) => [p.robotId, p] as const))("%s on the simulated robot", (_, plugin) => {
  it("records with each dispatch exactly what the robot received", async () => {
    const sim = await startSimulator({
      port: 0,
      nodes: simulatedRobot(plugin, { msPerChar: 0, animationMs: 10 }),
      ssh: { port: 0, username: "nao", password: PASSWORD },
    });
    const choice = transportFor(plugin, {
      rosbridgeUrl: sim.url,
      simulatorUrl: sim.url,
      ssh: { host: "127.0.0.1", port: sim.ssh!.port, username: "nao", password: PASSWORD },
    });
    if (!choice.ok) throw new Error(choice.reason);
    const robot = pluginRobot(plugin, choice.transport);
    try {
      const seen: Array<[string, string[], string[]]> = [];
      for (const action of plugin.actions) {
        const [frames, commands] = [sim.received.length, sim.ssh!.commands.length];
        const reports: RobotReport[] = [];
        const actionId = `${plugin.robotId}.${action.id}`;
        robot.perform(
          { actionId, actionType: robotActionType(plugin.robotId, action.id), parameters: parametersOf(action) },
          (r) => reports.push(r),
        );
        await expect.poll(() => reports.some((r) => r.kind !== "dispatched"), { timeout: 20_000 }).toBe(true);
        const detail = reports.find((r) => r.kind === "dispatched")?.detail;
        if (detail?.sent) dispatched.push({ actionId, detail });
        const received = [
          ...sim.received
            .slice(frames)
            .map((r) => r.message as { op: string; topic?: string; service?: string; action?: string; msg?: unknown })
            .filter((m) => ["publish", "call_service", "send_action_goal"].includes(m.op))
            .map(
              (m) => `${m.topic ?? m.service ?? m.action} ${JSON.stringify(m.msg ?? (m as { args?: unknown }).args)}`,
            ),
          ...sim.ssh!.commands.slice(commands).map((c) => `ssh ${c.command}`),
        ];
        seen.push([action.id, received, expectedOnWire(detail?.sent as Sent | undefined)]);
      }
      // Every action reached the robot (none is left to the browser here), and each as recorded.
      expect(seen.filter(([, received]) => received.length === 0).map(([id]) => id)).toEqual([]);
      for (const [id, received, recorded] of seen) expect([id, ...recorded]).toEqual([id, ...received]);
    } finally {
      robot.close();
      await sim.close();
    }
  });
});

describe("the trial's exports", () => {
  const opened = freshDatabase();
  afterAll(async () => (await opened).close());

  it("hold each recorded message unchanged: events CSV, trial JSON and the MCAP's robot commands", async () => {
    expect(dispatched.length).toBe(plugins.reduce((n, p) => n + p.actions.length, 0));
    const { db } = await opened;
    const f = await buildFixture(db);
    const owner = f.api("owner");
    const study = await f.newStudy();
    const { version } = await publishedVersion(owner, study.id);
    const trial = await owner.trials.create({ versionId: version.id });
    await appendEvents(
      db,
      { id: trial.id, lastSeq: 0, t0: null },
      dispatched.map((d) => ({ type: "action.dispatched" as const, ...d })),
      f.people.wizard.id,
    );
    const recorded = Object.fromEntries(dispatched.map((d) => [d.actionId, d.detail.sent]));
    const sentOf = (events: Array<{ type: string; actionId?: string; detail?: { sent?: unknown } }>) =>
      Object.fromEntries(events.filter((e) => e.type === "action.dispatched").map((e) => [e.actionId, e.detail?.sent]));

    const csv = parseCsv((await owner.trials.export({ trialId: trial.id, format: "csv" })).body as string);
    const payload = csv[0]!.indexOf("payload");
    expect(sentOf(csv.slice(1).map((row) => JSON.parse(row[payload]!)))).toEqual(recorded);

    const json = JSON.parse((await owner.trials.export({ trialId: trial.id, format: "json" })).body as string);
    expect(sentOf(json.events)).toEqual(recorded);

    const mcap = (await owner.trials.export({ trialId: trial.id, format: "mcap" })).body as Uint8Array;
    const reader = await McapIndexedReader.Initialize({
      readable: {
        size: async () => BigInt(mcap.length),
        read: async (at, n) => mcap.slice(Number(at), Number(at + n)),
      },
    });
    const commands = [...reader.channelsById.values()].find((c) => c.topic === "/hristudio/robot_commands")!;
    const messages: Array<{ type: string; actionId?: string; detail?: { sent?: unknown } }> = [];
    for await (const m of reader.readMessages({ topics: [commands.topic] }))
      messages.push(JSON.parse(new TextDecoder().decode(m.data)));
    expect(sentOf(messages)).toEqual(recorded);
  });
});
