// bench/trial-latency: wizard message in → robot message received by the
// simulated robot, and → every observer updated, for 1 trial and for 50
// concurrent trials with 10 observers each. Everything real: PostgreSQL,
// the runtime process as the launcher runs it, the NAO6 plugin, roslib and
// the simulator (here, in the bench's own process, so its arrivals are timed).
import { spawn } from "node:child_process";
import { join } from "node:path";
import { startDefaultSimulator } from "../src/robots/simulator/main";
import { SOCKET_MESSAGES_VERSION } from "../src/core/socket/messages";
import { freePort } from "../src/store/embedded";
import { createAccount } from "../src/server/auth/accounts";
import { createDatabase } from "../src/store/client";
import { experimentVersions, experiments, studies, studyMembers, trials } from "../src/store/schema";
import { signSocketToken } from "../src/store/socket-token";
import { report, scratchDatabase } from "./support";

const SECRET = "bench-secret".padEnd(40, "x");
const OBSERVERS = 10;
/** With many trials, each wizard sends at most one command per PACE_MS: ten a second, far above a person's pace. */
const PACE_MS = 100;

const database = await scratchDatabase();
const { db, close } = createDatabase(database.url, { max: 4 });
const sim = await startDefaultSimulator({ SIM_PORT: "0" });
const heard = new Map<string, (at: number) => void>();
const record = sim.received.push.bind(sim.received);
// Every message the robot receives, timed as it arrives.
sim.received.push = (...items) => {
  const at = performance.now();
  for (const item of items) {
    const text = (item.message.msg as { data?: string } | undefined)?.data;
    if (text) heard.get(text)?.(at);
  }
  return record(...items);
};

const runtimePort = await freePort();
const runtime = spawn(process.execPath, ["run", join(import.meta.dirname, "..", "src", "runtime", "main.ts")], {
  env: {
    ...process.env,
    DATABASE_URL: database.url,
    BETTER_AUTH_SECRET: SECRET,
    HRI_RUNTIME_PORT: String(runtimePort),
    HOST: "127.0.0.1",
    HRI_ROSBRIDGE_URL: sim.url,
  },
  stdio: ["ignore", "pipe", "inherit"],
});
await new Promise<void>((ok) => runtime.stdout!.on("data", (d) => String(d).includes("listening") && ok()));
const url = `ws://127.0.0.1:${runtimePort}`;

const wizardUser = await createAccount(db, {
  name: "Wizard",
  email: "w@bench",
  password: "bench-password",
  role: "wizard",
});
const observerUser = await createAccount(db, {
  name: "Observer",
  email: "o@bench",
  password: "bench-password",
  role: "observer",
});
const [study] = await db.insert(studies).values({ title: "Bench", status: "active" }).returning();
// The runtime looks each caller's role up in the study at hello.
await db.insert(studyMembers).values([
  { studyId: study!.id, userId: wizardUser.id, role: "wizard" },
  { studyId: study!.id, userId: observerUser.id, role: "observer" },
]);
const [experiment] = await db
  .insert(experiments)
  .values({ studyId: study!.id, name: "Bench", robotId: "nao6-ros2" })
  .returning();
const snapshot = {
  schemaVersion: 2 as const,
  experiment: { id: experiment!.id, name: "Bench", description: "", robotId: "nao6-ros2" },
  steps: [{ id: "s", name: "S", description: "", actions: [] }],
};
const [version] = await db
  .insert(experimentVersions)
  .values({ experimentId: experiment!.id, version: 1, snapshot, hash: "bench", robotId: "nao6-ros2" })
  .returning();

async function socket(
  trialId: string,
  userId: string,
  onEvents: (events: Array<{ type: string; parameters?: { text?: string } }>) => void,
) {
  const ws = new WebSocket(url);
  const pending = new Map<string, () => void>();
  await new Promise((ok) => (ws.onopen = ok));
  const welcomed = new Promise<void>((ok) => {
    ws.onmessage = (m) => {
      const message = JSON.parse(String(m.data));
      if (message.type === "welcome") ok();
      if (message.type === "events") onEvents(message.events);
      if (message.type === "ack" || message.type === "rejected") pending.get(message.requestId)?.();
    };
  });
  ws.send(
    JSON.stringify({
      type: "hello",
      version: SOCKET_MESSAGES_VERSION,
      token: signSocketToken({ userId, trialId }, SECRET),
      lastSeq: 0,
    }),
  );
  await welcomed;
  return {
    command: (command: Record<string, unknown>) =>
      new Promise<void>((ok) => {
        const requestId = crypto.randomUUID();
        pending.set(requestId, ok);
        ws.send(JSON.stringify({ type: "command", requestId, command }));
      }),
    close: () => ws.close(),
  };
}

/** One trial: a wizard and `observers` observers; `commands` unscripted lines, one after another, at most one per `paceMs`. */
async function runTrial(commands: number, toRobot: number[], toObservers: number[], paceMs = 0, observing = OBSERVERS) {
  const [trial] = await db
    .insert(trials)
    .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id })
    .returning();
  const seen = new Map<string, { left: number; done: (at: number) => void }>();
  const observe = (events: Array<{ type: string; parameters?: { text?: string } }>) => {
    const at = performance.now();
    for (const e of events) {
      const waiting = e.type === "action.requested" && e.parameters?.text ? seen.get(e.parameters.text) : undefined;
      if (waiting && --waiting.left === 0) waiting.done(at);
    }
  };
  const observers = await Promise.all(
    Array.from({ length: observing }, () => socket(trial!.id, observerUser.id, observe)),
  );
  const wizard = await socket(trial!.id, wizardUser.id, () => {});
  await wizard.command({ kind: "start" });
  for (let i = 0; i < commands; i++) {
    const text = `line ${trial!.id} ${i}`;
    const sent = performance.now();
    const robot = new Promise<void>((ok) =>
      heard.set(text, (at) => (toRobot.push(at - sent), heard.delete(text), ok())),
    );
    const everyone = new Promise<void>((ok) =>
      observing === 0
        ? ok()
        : seen.set(text, { left: observing, done: (at) => (toObservers.push(at - sent), seen.delete(text), ok()) }),
    );
    await wizard.command({ kind: "unscripted", actionType: "say", parameters: { text } });
    await Promise.all([robot, everyone]);
    const rest = paceMs - (performance.now() - sent);
    if (rest > 0) await new Promise((r) => setTimeout(r, rest));
  }
  [wizard, ...observers].forEach((s) => s.close());
}

const single = { robot: [] as number[], observers: [] as number[] };
await runTrial(30, [], []); // warm-up
await runTrial(1000, single.robot, single.observers);
report("1 trial: wizard message → robot received", single.robot, 5);
report("1 trial: wizard message → 10 observers updated", single.observers, 5);

const many = { robot: [] as number[], observers: [] as number[] };
await Promise.all(Array.from({ length: 50 }, () => runTrial(40, many.robot, many.observers, PACE_MS)));
report(`50 trials × 10 observers, 1 msg/${PACE_MS} ms each: → robot received`, many.robot, 25);
report(`50 trials × 10 observers, 1 msg/${PACE_MS} ms each: → all observers updated`, many.observers, 25);

const flood = { robot: [] as number[], observers: [] as number[] };
await Promise.all(Array.from({ length: 50 }, () => runTrial(20, flood.robot, flood.observers)));
report("50 trials × 10 observers, back to back (saturation): → robot", flood.robot);
report("50 trials × 10 observers, back to back (saturation): → observers", flood.observers);

// Many wizards at once, each sending its next line as soon as the robot has the last: what one runtime
// and one database carry. Each action is three commits' worth of events (requested, dispatched, completed).
const WIZARDS = 20;
const wizards = { robot: [] as number[] };
const began = performance.now();
await Promise.all(Array.from({ length: WIZARDS }, () => runTrial(150, wizards.robot, [], 0, 0)));
const seconds = (performance.now() - began) / 1000;
report(`${WIZARDS} wizards back to back: wizard message → robot`, wizards.robot, 25);
const perSecond = wizards.robot.length / seconds;
console.log(
  `${`${WIZARDS} wizards back to back: throughput`.padEnd(58)} n=${String(wizards.robot.length).padStart(6)}  ${perSecond.toFixed(0)} actions/s  target ≥ 1500: ${perSecond >= 1500 ? "met" : "NOT met"} (ratio ${(perSecond / 1500).toFixed(2)})`,
);

runtime.kill("SIGTERM");
await new Promise((ok) => runtime.once("exit", ok));
await sim.close();
await close();
await database.stop();
process.exit(0);
