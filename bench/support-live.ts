// The live-trial harness the runtime benchmarks share: a scratch PostgreSQL,
// the simulated robot in this process (so arrivals are timed as they land),
// the runtime as the launcher runs it, a study whose trials a wizard runs
// with unscripted lines while observers follow, and every refusal counted.
import { spawn } from "node:child_process";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import type { ProtocolSnapshot } from "../src/core/protocol/document";
import type { Simulator } from "../src/robots/simulator";
import { startDefaultSimulator } from "../src/robots/simulator/main";
import { withRuntimeEngine } from "../src/launcher/runtime-engine";
import { SOCKET_MESSAGES_VERSION } from "../src/core/socket/messages";
import { freePort } from "../src/store/embedded";
import { createAccount } from "../src/server/auth/accounts";
import { createDatabase } from "../src/store/client";
import { experimentVersions, experiments, robots, studies, studyMembers, trials } from "../src/store/schema";
import { signSocketToken } from "../src/store/socket-token";
import { scratchDatabase } from "./support";

/** Bun's client takes headers; the DOM's typing of WebSocket, which the project's types include, does not say so. */
const BunWebSocket = WebSocket as unknown as new (url: string, options: Bun.WebSocketOptions) => WebSocket;

/** The bench's one-step protocol, unless a bench brings its own steps. */
const ONE_EMPTY_STEP: ProtocolSnapshot["steps"] = [{ id: "s", name: "S", description: "", actions: [] }];

/** `steps`: the bench's protocol; `msPerChar`: how long the simulated robot takes to say each character (its default when unset). */
export async function startLiveBench({
  steps = ONE_EMPTY_STEP,
  msPerChar,
}: {
  steps?: ProtocolSnapshot["steps"];
  msPerChar?: number;
} = {}) {
  const SECRET = "bench-secret".padEnd(40, "x");
  let refused = 0;
  const reasons = new Set<string>();
  const OBSERVERS = 10;
  const database = await scratchDatabase();
  const { db, close } = createDatabase(database.url, { max: 4 });
  const heard = new Map<string, (at: number) => void>();
  /** The simulated robots, one per registered robot, and each one's row id, in the order they were added. */
  const sims: Simulator[] = [];
  const robotIds: string[] = [];

  /**
   * Registers robots until there are `count`, each its own simulated robot, as in a lab, where each robot is its
   * own rosbridge: robots sharing one would each hear every other's topics (their done messages, their state),
   * which no lab sees. Added when a bench needs them, so that a bench of one trial runs beside one robot's timers.
   */
  async function robotsUpTo(count: number) {
    while (sims.length < count) {
      const sim = await startDefaultSimulator({
        SIM_PORT: "0",
        ...(msPerChar === undefined ? {} : { SIM_MS_PER_CHAR: String(msPerChar) }),
      });
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
      const [robot] = await db
        .insert(robots)
        .values({ name: `Bench robot ${sims.length + 1}`, simulated: true, rosbridgeUrl: sim.url, allStudies: true })
        .returning({ id: robots.id });
      sims.push(sim);
      robotIds.push(robot!.id);
    }
  }

  const runtimePort = await freePort();
  // BENCH_PROFILE=<folder>: the runtime writes a CPU profile there as it stops, to find a tail's cause: the
  // .cpuprofile (Chrome DevTools, speedscope), whose samples are counted where they fell; Bun's Markdown
  // summary charges the idle time to the function that ran last.
  const profile = process.env.BENCH_PROFILE ? ["--cpu-prof", `--cpu-prof-dir=${process.env.BENCH_PROFILE}`] : [];
  const main = join(import.meta.dirname, "..", "src", "runtime", "main.ts");
  const runtime = spawn(process.execPath, [...profile, "run", main], {
    env: {
      ...withRuntimeEngine(process.env),
      DATABASE_URL: database.url,
      BETTER_AUTH_SECRET: SECRET,
      HRI_RUNTIME_PORT: String(runtimePort),
      HOST: "127.0.0.1",
      // No robot from the environment: the bench's robots are the registered ones, each its own simulator.
      HRI_ROSBRIDGE_URL: undefined,
      // Each socket stands in for a browser of its own: the bench says which, as a lab's proxy
      // would, so the runtime's cap on connections per address that have not said hello counts
      // browsers rather than this one process.
      HRI_TRUSTED_PROXIES: "127.0.0.1",
    },
    stdio: ["ignore", "pipe", "inherit"],
  });
  await new Promise<void>((ok) => runtime.stdout!.on("data", (d) => String(d).includes("listening") && ok()));
  // A bench that fails takes its runtime with it, rather than leave it running on its own.
  process.on("exit", () => runtime.kill("SIGKILL"));
  const url = `ws://127.0.0.1:${runtimePort}`;
  let browsers = 0;

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
  // A robot drives one live trial at a time: two to begin with (a trial, and the last one still letting go).
  await robotsUpTo(2);
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
    schemaVersion: 5 as const,
    experiment: { id: experiment!.id, name: "Bench", description: "", robotId: "nao6-ros2" },
    steps,
  };
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot, hash: "bench", robotId: "nao6-ros2" })
    .returning();

  /** The messages a bench browser reads, and where a message's type starts in its text. */
  const READ = new Set(["welcome", "events", "ack", "rejected"]);
  const TYPE_AT = '{"type":"'.length;

  /**
   * A browser's socket on the trial. `onEvents` gets each batch of events with when it arrived; with `wants`, only
   * the batches whose text holds it are parsed: the many browsers live in this one process, where a browser's own
   * parsing (on its own computer in a lab) would stand between the runtime and the next browser's timing.
   */
  async function socket(
    trialId: string,
    userId: string,
    onEvents: (events: Array<{ type: string; parameters?: { text?: string } }>, at: number) => void,
    wants?: string,
  ) {
    browsers++;
    // A documentation address (192.0.2.0/24) per socket, only ever a header: nothing is sent there.
    const ws = new BunWebSocket(url, { headers: { "x-forwarded-for": `192.0.2.${browsers % 250}` } });
    /** Each command's answer: null once acknowledged, else why it was refused. */
    const pending = new Map<string, (refusal: string | null) => void>();
    await new Promise((ok) => (ws.onopen = ok));
    const welcomed = new Promise<void>((ok, fail) => {
      // Shut before its welcome (an expired link, an overloaded runtime): the bench says why rather than wait.
      ws.onclose = (e) => fail(new Error(`The runtime closed a socket before its welcome: ${e.reason || e.code}`));
      ws.onmessage = (m) => {
        const at = performance.now();
        const text = String(m.data);
        // Every message begins {"type":"…": what the bench does not read (the robot's camera frames, five a
        // second to every browser, its state, presence) is never parsed.
        const type = text.slice(TYPE_AT, text.indexOf('"', TYPE_AT));
        if (!READ.has(type) || (wants && type === "events" && !text.includes(wants))) return;
        const message = JSON.parse(text);
        if (message.type === "welcome") ok();
        if (message.type === "events") onEvents(message.events, at);
        if (message.type === "rejected") {
          refused++;
          // Each reason once: a bench that is refused should say why.
          if (!reasons.has(message.reason)) console.error(`refused: ${message.reason}`);
          reasons.add(message.reason);
        }
        if (message.type === "ack") pending.get(message.requestId)?.(null);
        if (message.type === "rejected") pending.get(message.requestId)?.(String(message.reason));
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
    /** Sends a request; resolves with null once acknowledged, else why it was refused. */
    const ask = (message: Record<string, unknown>) =>
      new Promise<string | null>((ok) => {
        const requestId = crypto.randomUUID();
        pending.set(requestId, ok);
        ws.send(JSON.stringify({ ...message, requestId }));
      });
    return {
      command: (command: Record<string, unknown>) => ask({ type: "command", command }),
      /** Says whether this page shows the robot's camera (a page starts showing it, as the trial page does). */
      camera: (watch: boolean) => ask({ type: "camera", watch }),
      close: () => ws.close(),
    };
  }

  /**
   * One trial: a wizard and `observing` observers (10 unless said); `commands` unscripted lines, one after
   * another, at most one per `paceMs`. `toObservers` gets each line's time until the last observer has it;
   * `toEach`, when given, each observer's own times, one list per observer. `together` (a `group`), when
   * given, holds the lines until every trial of the group has started (its robot linked, its observers
   * welcomed), and the end until every trial has sent its lines: the group's figures are those of trials
   * running side by side, not of trials starting or ending beside them. `cameraHidden`: the observers' pages
   * do not show the robot's camera (hidden tabs, the panel closed), as they say; the wizard's page shows it.
   */
  async function runTrial(
    commands: number,
    toRobot: number[],
    toObservers: number[],
    {
      paceMs = 0,
      observing = OBSERVERS,
      toEach,
      together,
      cameraHidden = false,
    }: {
      paceMs?: number;
      observing?: number;
      toEach?: number[][];
      together?: ReturnType<typeof group>;
      cameraHidden?: boolean;
    } = {},
  ) {
    const trial = await newTrial();
    const seen = new Map<string, { sent: number; left: number; done: (at: number) => void }>();
    const observe = (k: number) => (events: Array<{ type: string; parameters?: { text?: string } }>, at: number) => {
      for (const e of events) {
        const waiting = e.type === "action.requested" && e.parameters?.text ? seen.get(e.parameters.text) : undefined;
        if (!waiting) continue;
        toEach?.[k]?.push(at - waiting.sent);
        if (--waiting.left === 0) waiting.done(at);
      }
    };
    const observers = await Promise.all(
      Array.from({ length: observing }, (_, k) => socket(trial!.id, observerUser.id, observe(k), '"action.requested"')),
    );
    if (cameraHidden) await Promise.all(observers.map((o) => o.camera(false)));
    const wizard = await socket(trial!.id, wizardUser.id, () => {});
    const starting = performance.now();
    const notStarted = await wizard.command({ kind: "start" });
    if (notStarted) throw new Error(`The runtime refused to start a trial: ${notStarted}`);
    together?.toStart.push(performance.now() - starting);
    await together?.started();
    for (let i = 0; i < commands; i++) {
      const text = `line ${trial!.id} ${i}`;
      const sent = performance.now();
      const robot = new Promise<void>((ok) =>
        heard.set(text, (at) => (toRobot.push(at - sent), heard.delete(text), ok())),
      );
      const everyone = new Promise<void>((ok) =>
        observing === 0
          ? ok()
          : seen.set(text, {
              sent,
              left: observing,
              done: (at) => (toObservers.push(at - sent), seen.delete(text), ok()),
            }),
      );
      // A line refused (counted, its reason said) never reaches the robot: the next is sent.
      if (!(await wizard.command({ kind: "unscripted", actionType: "say", parameters: { text } })))
        await Promise.all([robot, everyone]);
      else {
        heard.delete(text);
        seen.delete(text);
      }
      const rest = paceMs - (performance.now() - sent);
      if (rest > 0) await new Promise((r) => setTimeout(r, rest));
    }
    await together?.sent();
    // Ended, so that its robot is free for the next trial.
    await wizard.command({ kind: "complete" });
    [wizard, ...observers].forEach((s) => s.close());
    return trial!.id;
  }

  /**
   * Trials run side by side (runTrial's `together`): `size` of them, their start times into `toStart`. Once all
   * have started, each begins its lines at its own moment within the first `paceMs`, as wizards who do not
   * press together would: released at once, every trial's line would come in the same instant, each time.
   */
  function group(size: number, paceMs: number, toStart: number[]) {
    const allStarted = barrier(size);
    let joined = 0;
    return {
      started: async () => {
        const phase = (joined++ / size) * paceMs;
        await allStarted();
        await new Promise((r) => setTimeout(r, phase));
      },
      sent: barrier(size),
      toStart,
    };
  }

  /**
   * Resolves once no robot is speaking: a phase's figures are not those of a robot still saying the last phase's
   * lines (a thousand lines sent in two seconds take three to say), whose done messages the next trial on that
   * robot would hear. In a lab, the next session begins with the robot quiet.
   */
  async function quiet() {
    while (sims.some((sim) => sim.state.speaking !== null)) await new Promise((r) => setTimeout(r, 50));
  }

  /** A new trial of the bench's study, not yet started; on `sims[robot]` when `robot` is given, else on a free one. */
  async function newTrial(robot?: number) {
    const [trial] = await db
      .insert(trials)
      .values({
        studyId: study!.id,
        experimentId: experiment!.id,
        versionId: version!.id,
        assignedRobotId: robot === undefined ? null : robotIds[robot]!,
      })
      .returning();
    return trial!;
  }

  /**
   * The looping benches' run ("Wait", then `sayStep`, and back): a wizard on the trial starts it, presses Next
   * the moment it enters "Say" `via` its wait, and again once the line is said (back to "Wait"), until the
   * robot has received `line` `count` times. `onWait` is told each time the trial enters "Wait" until then;
   * `beforeStart` runs once the wizard has said hello. Each receipt's time is on this process's clock.
   */
  async function loop(
    trialId: string,
    options: {
      line: string;
      via: string;
      count: number;
      onWait?: () => void;
      /** The wizard pressed Next as the trial entered "say" by `via`, at this moment of the bench's clock. */
      onPress?: (at: number) => void;
      beforeStart?: () => Promise<void>;
    },
  ) {
    const receipts: number[] = [];
    let done: () => void;
    const finished = new Promise<void>((ok) => (done = ok));
    heard.set(options.line, (at) => {
      receipts.push(at);
      if (receipts.length === options.count) done();
    });
    let refusedPresses = 0;
    const wizard = await socket(trialId, wizardUser.id, (events) => {
      for (const e of events as Array<{ type: string; stepId?: string; via?: string; actionId?: string }>) {
        if (e.type === "step.entered" && e.stepId === "wait" && receipts.length < options.count) options.onWait?.();
        const press =
          (e.type === "step.entered" && e.stepId === "say" && e.via === options.via) ||
          (e.type === "action.completed" && e.actionId === "line");
        if (!press) continue;
        if (e.type === "step.entered") options.onPress?.(performance.now());
        void wizard.command({ kind: "next" }).then((refusal) => refusal && refusedPresses++);
      }
    });
    await options.beforeStart?.();
    const began = performance.now();
    const refused = await wizard.command({ kind: "start" });
    if (refused) throw new Error(`The runtime refused to start the trial: ${refused}`);
    await finished;
    const seconds = (performance.now() - began) / 1000;
    await wizard.command({ kind: "complete" });
    wizard.close();
    return { receipts, seconds, refusedPresses };
  }

  return {
    db,
    loop,
    newTrial,
    socket,
    /** The simulated robots, one per registered robot: each one's address (a Robot page's, to fire its senses) and what it has received. */
    sims,
    robotsUpTo,
    /** The robot's listeners by the text it hears: each is told when that text arrives. */
    heard,
    wizardId: wizardUser.id,
    /**
     * How many events the welcome of an observer's hello carries with its parts, once it has come. Counted
     * in their text, not parsed: parsing a 10 MB log here would stall this process, the simulated robot's too.
     */
    async welcomeOf(trialId: string) {
      const ws = new WebSocket(url);
      await new Promise((ok) => (ws.onopen = ok));
      let events = 0;
      const welcome = new Promise<void>((ok) => {
        ws.onmessage = (m) => {
          const text = String(m.data);
          if (text.startsWith('{"type":"welcome')) events += text.split('"seq":').length - 1;
          if (text.startsWith('{"type":"welcome"')) ok();
        };
      });
      ws.send(
        JSON.stringify({
          type: "hello",
          version: SOCKET_MESSAGES_VERSION,
          token: signSocketToken({ userId: observerUser.id, trialId }, SECRET),
          lastSeq: 0,
        }),
      );
      await welcome;
      ws.close();
      return events;
    },
    runTrial,
    group,
    quiet,
    /** The runtime's process id (its CPU is counted by it: support-cpu.ts). */
    runtimePid: runtime.pid!,
    /** The runtime's resident memory now, in MiB. */
    runtimeMemoryMiB: () =>
      Number(/VmRSS:\s+(\d+)/.exec(readFileSync(`/proc/${runtime.pid}/status`, "utf8"))![1]) / 1024,
    /**
     * What the trials' logs cost in commits: rows of one transaction share its xmin. `perTrial`: the
     * commits that wrote each trial's events, summed (what one trial waits through); `overall`: the
     * transactions that wrote any of them (one commit carries many trials'); and the actions requested.
     */
    async commits(trialIds: string[]) {
      const ids = db.$client(trialIds);
      const [row] = await db.$client<Array<{ per_trial: string; overall: string; actions: string }>>`
        select
          (select count(*) from (select distinct trial_id, xmin::text from trial_events where trial_id in ${ids}) t) as per_trial,
          (select count(distinct xmin::text) from trial_events where trial_id in ${ids}) as overall,
          (select count(*) from trial_events where trial_id in ${ids} and type = 'action.requested') as actions`;
      return { perTrial: Number(row!.per_trial), overall: Number(row!.overall), actions: Number(row!.actions) };
    },
    /** Commands the runtime refused so far. */
    refused: () => refused,
    async stop() {
      runtime.kill("SIGTERM");
      await new Promise((ok) => runtime.once("exit", ok));
      await Promise.all(sims.map((sim) => sim.close()));
      await close();
      await database.stop();
    },
  };
}

/** Resolves each caller once `size` callers have come. */
function barrier(size: number) {
  let arrived = 0;
  let open: () => void;
  const opened = new Promise<void>((ok) => (open = ok));
  return () => {
    if (++arrived === size) open();
    return opened;
  };
}

/** The looping benches' second step: one line, then back to "Wait" (the first step, each bench's own). */
export function sayStep(line: string): ProtocolSnapshot["steps"][number] {
  return {
    id: "say",
    name: "Say",
    description: "",
    after: { to: "step", stepId: "wait" },
    actions: [{ id: "line", type: "say", name: "", parameters: { text: line }, parallelGroup: null }],
  };
}
