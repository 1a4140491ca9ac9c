// The trial runtime over real sockets: the wizard commands, observers watch
// and annotate but cannot command, and kill -9 of the runtime or of
// PostgreSQL loses and duplicates nothing the wizard saw acknowledged.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { childPid, DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";
import { connectTrial, type TrialSocket } from "../support/socket";

type Api = ReturnType<typeof apiClient>;
const seqsOf = (sockets: TrialSocket) =>
  sockets.messages.flatMap((m) => ((m.events as Array<{ seq: number }> | undefined) ?? []).map((e) => e.seq));

describe.sequential("a live trial through the runtime", () => {
  let app: RunningApp;
  let wizardApi: Api;
  let observerApi: Api;
  let trialId = "";

  beforeAll(async () => {
    app = await startApp();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    observerApi = apiClient(app.url, await signIn(app.url, "observer@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    trialId = (await wizardApi.trials.create.mutate({ versionId: version.id, participantId: participant!.id })).id;
  });
  afterAll(async () => app?.stop());

  const open = async (api: Api, lastSeq = 0) => {
    const { url, token } = await api.trials.socketToken.mutate({ trialId });
    expect(url).toBe(app.runtimeUrl);
    return connectTrial(url, token, lastSeq);
  };

  it("acknowledges the wizard's commands after they are stored, and pushes them to observers", async () => {
    const wizard = await open(wizardApi);
    const observer = await open(observerApi);
    expect(await wizard.command("r1", { kind: "start" })).toMatchObject({ type: "ack", seqs: [1, 2] });
    await observer.next((m) => m.type === "events" && seqsOf({ ...observer, messages: [m] }).includes(2));
    const stored = await wizardApi.trials.get.query({ trialId });
    expect(stored.status).toBe("in_progress");
    // The simulated robot's joint states are logged, timed from t0, in batches.
    let samples: Awaited<ReturnType<Api["trials"]["samples"]["query"]>> = [];
    for (let i = 0; i < 50 && samples.length < 3; i++) {
      await new Promise((r) => setTimeout(r, 100));
      samples = await observerApi.trials.samples.query({ trialId, topic: "/joint_states" });
    }
    expect(samples.length).toBeGreaterThanOrEqual(3);
    expect(samples[0]!.relMs).toBeGreaterThanOrEqual(0);
    expect(samples[0]!.data).toMatchObject({ name: expect.any(Array), position: expect.any(Array) });
    await expect(wizardApi.trials.samples.query({ trialId })).rejects.toMatchObject({ data: { code: "FORBIDDEN" } });
    wizard.close();
    observer.close();
  });

  it("never lets an observer command, but lets them annotate everyone sees", async () => {
    const wizard = await open(wizardApi);
    const observer = await open(observerApi);
    expect(await observer.command("o1", { kind: "next" })).toMatchObject({
      type: "rejected",
      reason: "As observer you may watch this trial but not run it.",
    });
    observer.send({ type: "annotate", requestId: "a1", label: "Participant laughed", note: "" });
    await observer.next((m) => m.type === "ack" && m.requestId === "a1");
    const seen = await wizard.next((m) => m.type === "annotation");
    expect(seen).toMatchObject({ annotation: { label: "Participant laughed", authorName: "Olu Observer" } });
    wizard.close();
    observer.close();
  });

  it("refuses messages it does not understand and tokens it did not sign", async () => {
    const wizard = await open(wizardApi);
    wizard.send({ type: "command", requestId: "x", command: { kind: "fly" } });
    expect((await wizard.next((m) => m.type === "rejected")).reason).toMatch(
      /^The message is not understood: command.kind/,
    );
    wizard.close();
    const forged = await connectTrial(app.runtimeUrl, "forged.token");
    expect(forged.closed).toEqual({ code: 4401, reason: "Your link to this trial has expired. Reload the page." });
    expect(forged.messages).toEqual([]);
  });

  it("sends a long log's welcome whole, and what is logged while it is written after it, in order", {
    timeout: 120_000,
  }, async () => {
    const wizard = await open(wizardApi);
    // More events than one page of a welcome's text (the runtime writes it a page at a time), a hundred at a time.
    for (let batch = 0; batch < 22; batch++)
      await Promise.all(
        Array.from({ length: 100 }, (_, i) =>
          wizard.command(`n${batch}-${i}`, { kind: "note", text: `Note ${batch}-${i}` }),
        ),
      );
    const more = Promise.all(
      Array.from({ length: 100 }, (_, i) => wizard.command(`m${i}`, { kind: "note", text: `More ${i}` })),
    );
    const observer = await open(observerApi);
    await more;
    const last = Math.max(...((await wizard.command("last", { kind: "note", text: "Last" })).seqs as number[]));
    await observer.next(() => seqsOf(observer).includes(last));
    const seen = seqsOf(observer);
    expect(seen).toEqual(Array.from({ length: last }, (_, i) => i + 1));
    wizard.close();
    observer.close();
  });

  it("misses nothing for observers who join while the wizard's lines stream in", { timeout: 120_000 }, async () => {
    // Found by CI: a hello read the log, then subscribed to the host; an event committed after the read's
    // snapshot and given out before the subscription reached that observer never (seq 2,209 of 2,294). And
    // one committed before the read but given out by the host after the welcome reached it twice (seq
    // 2,569): a hundred observers joining meet that every run on the code before its mend (3 of 3).
    const wizard = await open(wizardApi);
    // The observers' links asked for before the lines stream: during it each join is a connection and a hello.
    const links = await Promise.all(
      Array.from({ length: 100 }, () => observerApi.trials.socketToken.mutate({ trialId })),
    );
    let streaming = true;
    const stream = (async () => {
      for (let batch = 0; streaming; batch++)
        await Promise.all(
          Array.from({ length: 10 }, (_, i) =>
            wizard.command(`s${batch}-${i}`, { kind: "note", text: `Streamed ${batch}-${i}` }),
          ),
        );
    })();
    // Each from what the wizard's page has seen so far, as a page coming back does: sixty whole logs would
    // hold this process (and its HTTP client's timers) for seconds.
    const observers: Array<{ observer: TrialSocket; from: number }> = [];
    for (const { url, token } of links) {
      const from = Math.max(0, ...seqsOf(wizard));
      const observer = await connectTrial(url, token, from);
      await observer.next((m) => m.type === "welcome");
      observers.push({ observer, from });
    }
    streaming = false;
    await stream;
    const last = Math.max(...((await wizard.command("joined", { kind: "note", text: "All in" })).seqs as number[]));
    for (const { observer, from } of observers) {
      await observer.next(() => seqsOf(observer).includes(last));
      expect(seqsOf(observer)).toEqual(Array.from({ length: last - from }, (_, i) => from + 1 + i));
      observer.close();
    }
    wizard.close();
  });

  it("survives kill -9 of the runtime: the wizard resumes with nothing lost or repeated", async () => {
    const wizard = await open(wizardApi);
    const r2 = await wizard.command("r2", { kind: "next" });
    const acked = seqsOf(wizard);
    const lastSeen = Math.max(...acked);
    const runtimePid = childPid(app, "runtime/main.ts");
    // Started by the launcher with its engine's settings (src/launcher/runtime-engine.ts).
    expect(readFileSync(`/proc/${runtimePid}/environ`, "utf8").split("\0")).toContain("BUN_JSC_useFTLJIT=false");
    process.kill(runtimePid, "SIGKILL");
    // The launcher starts a new runtime; the wizard reconnects from what it saw.
    let resumed: TrialSocket | null = null;
    for (let i = 0; i < 100 && !resumed; i++) {
      resumed = await open(wizardApi, lastSeen).catch(() => null);
      if (!resumed) await new Promise((r) => setTimeout(r, 100));
    }
    const welcome = resumed!.messages.find((m) => m.type === "welcome")!;
    const missed = (welcome.events as Array<{ seq: number }>).map((e) => e.seq);
    expect(missed.every((s) => s > lastSeen)).toBe(true);
    // Asked again by its id (the browser does so for what it sent before the drop): answered from the
    // log with its first outcome, not carried out a second time.
    resumed!.send({ type: "command", requestId: "r2", command: { kind: "next" }, retry: true });
    expect(await resumed!.next((m) => m.requestId === "r2")).toEqual(r2);
    const next = await resumed!.command("r3", { kind: "next" });
    expect(next.type).toBe("ack");
    const all = await wizardApi.trials.get.query({ trialId });
    expect(all.status).toBe("in_progress");
    const seqs = [...acked, ...missed, ...(next.seqs as number[])];
    expect(new Set(seqs).size).toBe(seqs.length);
    expect(Math.min(...(next.seqs as number[]))).toBeGreaterThan(lastSeen);
    resumed!.close();
  });

  it("carries on through kill -9 of PostgreSQL: refused while it is down, restarted by the launcher, nothing lost or repeated", async () => {
    const wizard = await open(wizardApi);
    const before = await wizard.command("p1", { kind: "note", text: "before the database died" });
    expect(before.type).toBe("ack");
    const runtimePid = childPid(app, "runtime/main.ts");
    const postmaster = Number(readFileSync(join(app.dataDir, "postgres", "postmaster.pid"), "utf8").split("\n")[0]);
    process.kill(postmaster, "SIGKILL");
    // Its backends may finish what they hold before they notice: whatever is acknowledged counts. Once it
    // is down, a command is refused, plainly, and not held to be carried out later.
    const acknowledged = [before];
    let down: Record<string, unknown> = {};
    for (let i = 0; i < 50 && down.type !== "rejected"; i++) {
      down = await wizard.command(`p2-${i}`, { kind: "note", text: `while the database dies ${i}` });
      if (down.type === "ack") acknowledged.push(down);
    }
    expect(down.type).toBe("rejected");
    expect(String(down.reason)).not.toMatch(/SQL|ECONN|postgres/i);
    // The launcher starts it again; the same runtime carries on, and the same socket is acknowledged. Until
    // then each command is answered (refused, or not confirmed in time), never left without an answer.
    let after: Record<string, unknown> = {};
    let text = "";
    for (let i = 0; i < 150 && after.type !== "ack"; i++) {
      text = `after the database came back ${i}`;
      after = await wizard.command(`p3-${i}`, { kind: "note", text });
      if (after.type !== "ack") await new Promise((r) => setTimeout(r, 200));
    }
    expect(after.type).toBe("ack");
    expect(childPid(app, "runtime/main.ts")).toBe(runtimePid);
    expect(app.output()).toContain("PostgreSQL stopped unexpectedly; restarting it.");
    // Every acknowledged event is in the log once, and nothing twice: the socket was sent the whole log at
    // hello and every event after it. Refused plainly (the database was not there), a note is not in the log.
    const logged = wizard.messages.flatMap(
      (m) => (m.events as Array<{ seq: number; type: string; text?: string }> | undefined) ?? [],
    );
    const seqs = logged.map((e) => e.seq);
    expect(seqs).toEqual(seqs.map((_, i) => i + 1));
    for (const reply of [...acknowledged, after]) for (const seq of reply.seqs as number[]) expect(seqs).toContain(seq);
    const notes = logged.filter((e) => e.type === "note.added").map((e) => e.text);
    expect(notes).toContain("before the database died");
    expect(notes.filter((n) => n === text)).toHaveLength(1);
    expect(new Set(notes).size).toBe(notes.length);
    const refusedPlainly = wizard.messages.filter(
      (m) => m.type === "rejected" && String(m.reason).startsWith("The trial log is not answering"),
    );
    expect(refusedPlainly.length).toBeGreaterThan(0);
    const sent = new Map(
      [...Array(150).keys()].flatMap((i) => [
        [`p2-${i}`, `while the database dies ${i}`],
        [`p3-${i}`, `after the database came back ${i}`],
      ]),
    );
    for (const refusal of refusedPlainly) expect(notes).not.toContain(sent.get(String(refusal.requestId)));
    wizard.close();
  }, 120_000);
});
