// A wizard runs the whole Interactive Storyteller with the keyboard only,
// while an observer in another browser watches each step change and marks a
// annotation the wizard sees.
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { childPid, DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { signalDatabase } from "../support/frozen-postgres";
import { expectAccessible } from "../support/accessibility";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { explained } from "../support/explain";
import { connectTrial } from "../support/socket";
import { scoreRun } from "../support/storyteller-run-checklist";

describe.sequential("a live trial in two browsers", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialPath = "";
  let wizardApi: ReturnType<typeof apiClient>;
  // Reads the log as the analysis does: the trial's data is for researchers, not wizards.
  let researcherApi: ReturnType<typeof apiClient>;
  // What a new trial of the Storyteller is made from.
  let newTrial = { versionId: "", participantId: "" };

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    researcherApi = researcher;
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    newTrial = { versionId: version.id, participantId: participant!.id };
    trialPath = `/trials/${(await wizardApi.trials.create.mutate(newTrial)).id}`;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  const currentStep = (page: Page) => page.getByTestId("current-step").textContent();

  it("runs the Storyteller from the keyboard while an observer follows and annotates", async () => {
    const wizard = await (await newContext(browser, app.url)).newPage();
    const observer = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await signInAs(observer, "observer@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(trialPath);
    await observer.goto(trialPath);
    await wizard.getByText("live", { exact: true }).waitFor();
    await observer.getByText("live", { exact: true }).waitFor();
    await wizard.getByText("Olu Observer (observer)").waitFor();
    // The robot the trial drives is connected once the runtime has opened the trial: a wizard waits for it.
    await wizard.getByText("robot connected").waitFor();

    const press = async (key: string, then: () => Promise<unknown>) => {
      await wizard.keyboard.press(key);
      await then();
    };
    const stepIs = async (page: Page, name: string) => expect.poll(() => currentStep(page)).toBe(name);
    const allDone = () =>
      expect
        .poll(
          async () =>
            (await wizard.locator('[data-testid^="action-"]').allTextContents()).every((t) =>
              /^(done|skipped)/.test(t),
            ),
          { timeout: 10_000 },
        )
        .toBe(true)
        .catch(async (e: Error) => {
          // Say what the log holds, so a failure here can be read without rerunning.
          const log = await researcherApi.trials.events.query({ trialId: trialPath.split("/").pop()! });
          throw new Error(
            `${e.message}\nTrial log: ${JSON.stringify(log.map((x) => [x.seq, x.type, "actionId" in x ? x.actionId : "", "reason" in x ? x.reason : ""]))}`,
          );
        });

    await press("n", () => stepIs(wizard, "Introduction"));
    await stepIs(observer, "Introduction");
    await press("n", allDone);
    await screenshot(wizard, "wizard-view");
    await press("n", () => stepIs(wizard, "Story"));
    await stepIs(observer, "Story");
    // The wizard reads the whole line, not its name cut at 32 characters.
    expect(await wizard.getByTestId("line-text").first().textContent()).toMatch(/carried it back to the base\.$/);
    await press("n", allDone);
    await press("n", () => stepIs(wizard, "Recall question"));
    await stepIs(observer, "Recall question");
    // The pause holds the protocol: N during it is refused, and the question waits.
    await press("n", () =>
      expect
        .poll(async () => (await wizard.locator('[data-testid^="action-"]').first().textContent()) ?? "")
        .toMatch(/^(sent|running)/),
    );
    await wizard.keyboard.press("n");
    await wizard.getByRole("alert").filter({ hasText: "Wait: the 2 s pause is still running." }).waitFor();
    await expect
      .poll(async () => (await wizard.locator('[data-testid^="action-"]').first().textContent()) ?? "", {
        timeout: 5000,
      })
      .toMatch(/^done/);
    // Its cause over, the refusal leaves the page by itself.
    await expect.poll(() => wizard.getByText("Wait: the 2 s pause is still running.").count()).toBe(0);
    await press("n", () => wizard.getByText("What did the participant answer?").waitFor());

    await observer.getByLabel("Label").fill("Participant hesitated");
    await observer.getByRole("button", { name: "Annotate" }).click();
    await wizard.getByRole("list", { name: "Annotations" }).getByText("Participant hesitated").waitFor();
    await screenshot(observer, "observer-view");

    await press("1", () => stepIs(wizard, "Response — correct"));
    await stepIs(observer, "Response — correct");
    await press("n", () => wizard.getByRole("button", { name: /End$/ }).waitFor());
    // The robot says it has finished the response (and its nod) before the wizard ends the trial.
    await expect
      .poll(
        async () => {
          const log = await researcherApi.trials.events.query({ trialId: trialPath.split("/").pop()! });
          const asked = log.filter((e) => e.type === "action.requested").length;
          return log.filter((e) => /^action\.(completed|failed|timed_out|skipped)$/.test(e.type)).length >= asked;
        },
        { timeout: 15_000 },
      )
      .toBe(true);
    await press("n", () => expect.poll(() => observer.getByTestId("trial-status").textContent()).toBe("completed"));
    // A completed trial takes nothing more: its controls are off, emergency stop included, and the page says why.
    await wizard.getByText(/^This trial is completed: nothing more can be sent to it or to its robot/).waitFor();
    for (const name of ["Emergency stop (Esc)", "Abort trial…", "Pause (P)", "Add note"])
      expect(await wizard.getByRole("button", { name }).isDisabled(), name).toBe(true);

    // The log, checked against the protocol document's "run" checklist.
    const trialId = trialPath.split("/").pop()!;
    const trial = await wizardApi.trials.get.query({ trialId });
    const events = await researcherApi.trials.events.query({ trialId });
    expect(scoreRun(trial.protocol, events)).toEqual({ score: 100, failed: [] });

    // Afterwards: planned against executed, the timeline with the annotation, the joint angles.
    await observer.getByRole("link", { name: /Open the analysis/ }).click();
    await expect.poll(() => observer.getByTestId("figure-Execution fidelity").textContent()).toBe("100 %");
    await observer.getByRole("region", { name: "Timeline" }).getByText("Participant hesitated").waitFor();
    await observer.getByRole("img", { name: /Joint angles of/ }).waitFor();
    await screenshot(observer, "analysis");
    const csv = await observer.evaluate(
      async (id) => (await fetch(`/api/trials/${id}/export?format=csv`)).text(),
      trialId,
    );
    expect(csv.trim().split("\r\n")).toHaveLength(events.length + 1);
    const record = await observer.evaluate(
      async (id) => (await fetch(`/api/trials/${id}/export?format=json`)).json(),
      trialId,
    );
    expect(record).toMatchObject({
      schemaVersion: 3,
      protocol: { experiment: { name: "Interactive Storyteller" } },
      annotations: [{ label: "Participant hesitated" }],
    });
    // Wizards run trials; reading the data is for researchers and observers.
    expect(
      await wizard.evaluate(async (id) => (await fetch(`/api/trials/${id}/export?format=csv`)).status, trialId),
    ).toBe(403);
    await wizard.context().close();
    await observer.context().close();
  }, 60_000);

  it("shows an observer no wizard controls, and the wizard's keys do nothing for them", async () => {
    const observer = await (await newContext(browser, app.url)).newPage();
    await signInAs(observer, "observer@demo.hristudio", DEMO_PASSWORD);
    await observer.goto(trialPath);
    await observer.getByText("live", { exact: true }).waitFor();
    expect(await observer.getByRole("button", { name: /Emergency stop/ }).count()).toBe(0);
    await observer.keyboard.press("n");
    await observer.keyboard.press("Escape");
    expect(await observer.getByTestId("trial-status").textContent()).toBe("completed");
    expect(await observer.getByText("emergency stop").count()).toBe(0);
    await observer.context().close();
  });

  it("shows the wizard and an observer a frozen runtime as not answering, controls off, and live again once it resumes", async () => {
    const path = `/trials/${(await wizardApi.trials.create.mutate(newTrial)).id}`;
    const wizard = await (await newContext(browser, app.url)).newPage();
    const observer = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await signInAs(observer, "observer@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(path);
    await observer.goto(path);
    await wizard.getByText("robot connected").waitFor();
    await observer.getByText("live", { exact: true }).waitFor();
    await wizard.keyboard.press("n");
    await expect.poll(() => currentStep(wizard)).toBe("Introduction");
    const next = wizard.getByRole("button", { name: /^N\b/ });
    expect(await next.isDisabled()).toBe(false);
    const runtimeIs = (page: Page) => page.getByTestId("runtime-status").textContent();

    // Frozen, its sockets stay open: only the heartbeat can tell the pages. All of this is seen while it is frozen.
    const runtime = childPid(app, "runtime/main.ts");
    process.kill(runtime, "SIGSTOP");
    try {
      await expect.poll(() => runtimeIs(wizard), { timeout: 10_000 }).toBe("not answering");
      await expect.poll(() => runtimeIs(observer), { timeout: 10_000 }).toBe("not answering");
      await wizard.getByText(/^The trial runtime is not answering: nothing can be sent/).waitFor();
      expect(await next.isDisabled()).toBe(true);
      expect(await wizard.getByRole("button", { name: "Emergency stop (Esc)" }).isDisabled()).toBe(true);
      await expect.poll(() => wizard.getByTestId("robot-status").textContent()).toBe("unknown");
    } finally {
      process.kill(runtime, "SIGCONT");
    }
    // Back without a reload, on the same page: live, and the wizard can go on.
    await expect.poll(() => runtimeIs(wizard), { timeout: 20_000 }).toBe("live");
    await expect.poll(() => runtimeIs(observer), { timeout: 20_000 }).toBe("live");
    await expect.poll(() => next.isDisabled()).toBe(false);
    await wizard.keyboard.press("n");
    await expect
      .poll(
        async () =>
          (await wizard.locator('[data-testid^="action-"]').allTextContents()).some((t) => t.startsWith("done")),
        { timeout: 15_000 },
      )
      .toBe(true);
    // Ended, so that its robot is free for the trials after it.
    await wizard.getByRole("button", { name: "Complete trial" }).click();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent()).toBe("completed");
    await wizard.context().close();
    await observer.context().close();
  });

  it("rehearses the draft, and the wizard's page carries on after kill -9 of the runtime", async () => {
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.getByRole("link", { name: /Storytelling and memory/ }).click();
    await wizard.getByRole("tab", { name: "Experiments" }).click();
    await wizard.getByRole("button", { name: "Rehearse Interactive Storyteller" }).click();
    await wizard.waitForURL(/\/trials\//);
    await wizard.getByText("rehearsal", { exact: true }).waitFor();
    await wizard.getByText("robot connected").waitFor();
    await wizard.keyboard.press("n");
    await expect.poll(() => currentStep(wizard)).toBe("Introduction");
    await wizard.keyboard.press("n");
    // The robot takes its time to speak and wave; a loaded machine takes longer than poll's default second.
    await explained(
      expect
        .poll(
          async () =>
            (await wizard.locator('[data-testid^="action-"]').allTextContents()).every((t) => t.startsWith("done")),
          { timeout: 15_000 },
        )
        .toBe(true),
      { app, trialIds: [wizard.url().split("/").pop()!], pages: [wizard] },
    );

    // The launcher held (SIGSTOP) so the runtime stays down while the page is looked at.
    process.kill(app.process.pid!, "SIGSTOP");
    try {
      process.kill(childPid(app, "runtime/main.ts"), "SIGKILL");
      await wizard.getByText("reconnecting", { exact: true }).waitFor();
      // Each as it is: what the runtime said of the robot no longer holds; the database still answers.
      await expect.poll(() => wizard.getByTestId("robot-status").textContent()).toBe("unknown");
      await expect.poll(() => wizard.getByTestId("database-status").textContent()).toBe("connected");
      await wizard.getByText(/^The trial runtime is not connected: nothing can be sent/).waitFor();
      expect(await wizard.getByRole("button", { name: /Go to “Story”/ }).isDisabled()).toBe(true);
      expect(await wizard.getByRole("button", { name: "Emergency stop (Esc)" }).isDisabled()).toBe(true);
    } finally {
      process.kill(app.process.pid!, "SIGCONT");
    }
    await wizard.getByText("live", { exact: true }).waitFor({ timeout: 20_000 });
    // Same point, same state: the next action is still "Go to Story".
    await wizard.getByRole("button", { name: /Go to “Story”/ }).waitFor();
    await wizard.keyboard.press("n");
    await explained(expect.poll(() => currentStep(wizard)).toBe("Story"), {
      app,
      trialIds: [wizard.url().split("/").pop()!],
      pages: [wizard],
    });

    // Any robot action off script, from a form, logged as a deviation.
    await wizard.getByText("Unscripted robot action").click();
    await wizard.getByLabel("Action").selectOption({ label: "Posture" });
    await wizard.getByRole("button", { name: /Send “Posture”/ }).click();
    await wizard
      .getByText("must have required property")
      .or(wizard.getByText(/posture.*required|required.*posture/i))
      .first()
      .waitFor();
    await wizard.getByLabel("Action").selectOption({ label: "Nod" });
    await wizard.getByRole("button", { name: /Send “Nod”/ }).click();
    await wizard.getByRole("region", { name: "Off script" }).getByText(/^done/).waitFor();
    // Named as the library names it, not by its type.
    await wizard.getByRole("region", { name: "Off script" }).getByText("Nod", { exact: true }).waitFor();
    await expectAccessible(wizard, "the unscripted action form");
    // One the robot cannot do (sent past the form, as another client could): the reason, in words, beside its badge.
    const socket = await wizardApi.trials.socketToken
      .mutate({ trialId: wizard.url().split("/").pop()! })
      .then(({ url, token }) => connectTrial(url, token));
    await socket.command("cartwheel", {
      kind: "unscripted",
      actionType: "posture",
      parameters: { posture: "cartwheel" },
    });
    socket.close();
    const offScript = wizard.getByRole("region", { name: "Off script" });
    await offScript.getByText(/^failed/).waitFor();
    expect(await offScript.getByRole("alert").textContent()).toBe(
      'Posture: "Posture" must be one of: "stand", "sit", "crouch", "rest".',
    );

    // Off the designed path, by hand: each is allowed and logged with its kind.
    await wizard.getByText("Jump to another step (a deviation)").click();
    await wizard.getByRole("button", { name: "Jump to Recall question" }).click();
    await expect.poll(() => currentStep(wizard)).toBe("Recall question");
    await wizard.getByRole("button", { name: "Run Question now" }).click();
    await wizard
      .getByTestId(/action-/)
      .filter({ hasText: "Question" })
      .getByText("done")
      .waitFor();
    await wizard.keyboard.press("Escape");
    await expect.poll(() => wizard.getByTestId("emergency-stop").textContent()).toBe("emergency stop");
    // N while stopped is refused; the refusal lasts while its cause does, and no longer (below).
    const refused = wizard.getByRole("alert").filter({ hasText: "The trial is paused: resume it first." });
    await wizard.keyboard.press("n");
    await refused.waitFor();
    await wizard.getByRole("button", { name: "Abort trial…" }).click();
    await expectAccessible(wizard, "asked to confirm the abort");
    await wizard.getByRole("button", { name: "Confirm: abort this trial" }).click();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent()).toBe("aborted");
    // Ended, the trial's emergency stop is disarmed: no longer red, its button off, and the page says why.
    await wizard.getByText(/^This trial was aborted: nothing more can be sent to it or to its robot/).waitFor();
    expect(await wizard.getByTestId("emergency-stop").textContent()).toBe("emergency stop used");
    const stop = wizard.getByRole("button", { name: "Emergency stop (Esc)" });
    expect(await stop.isDisabled()).toBe(true);
    expect(await stop.getAttribute("class")).not.toMatch(/bg-red/);
    expect(await wizard.getByRole("button", { name: /Trial ended/ }).isDisabled()).toBe(true);
    expect(await refused.count()).toBe(0);

    const trialId = wizard.url().split("/").pop()!;
    const log = await researcherApi.trials.events.query({ trialId });
    const seqs = log.map((e) => e.seq);
    expect(seqs).toEqual(seqs.map((_, i) => i + 1));
    expect(log.filter((e) => e.deviation).map((e) => e.deviation)).toEqual([
      "unscripted",
      "unscripted",
      "manual_jump",
      "out_of_order",
    ]);
    expect((await wizardApi.trials.get.query({ trialId })).isRehearsal).toBe(true);
    await wizard.context().close();
  }, 60_000);

  it("shows on the robot page what the simulated robot is doing", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "observer@demo.hristudio", DEMO_PASSWORD);
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await page.getByText("connected", { exact: true }).waitFor();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const [version] = await researcher.versions.list.query({ experimentId: experiment!.id });
    const trial = await wizardApi.trials.create.mutate({ versionId: version!.id });
    const { url, token } = await wizardApi.trials.socketToken.mutate({ trialId: trial.id });
    const wizard = await connectTrial(url, token);
    await wizard.command("s", { kind: "start" });
    await wizard.command("u", {
      kind: "unscripted",
      actionType: "say",
      parameters: { text: 'She said "hi" {{name}} & left.' },
    });
    await wizard.command("w", { kind: "unscripted", actionType: "wave", parameters: {} });
    await page.getByRole("status", { name: "Robot speech" }).getByText('“She said "hi" {{name}} & left.”').waitFor();
    await wizard.command("u2", { kind: "unscripted", actionType: "say", parameters: { text: "And back." } });
    // Every line of the last few stays on the page, not only the last one.
    const lines = page.getByRole("region", { name: "Lines said" }).getByRole("listitem");
    // Newest first: the earlier trials of this file said theirs before.
    await expect
      .poll(async () => (await lines.allTextContents()).slice(0, 2).join("\n"), { timeout: 10_000 })
      .toMatch(/And back\.\n.*She said "hi" \{\{name\}\} & left\./);
    await expect.poll(() => page.getByTestId("robot-gesture").textContent()).not.toBe("none");
    // The NAO's wave is an animation path on the wire; the page names it, and shows no Markdown.
    expect(await page.getByTestId("robot-gesture").textContent()).not.toContain("/");
    expect(await page.getByRole("main").textContent()).not.toContain("`");
    await screenshot(page, "robot-view");
    wizard.close();
    await page.context().close();
  });

  it("asks again, after a dropped connection, what became of a command: carried out once, and the page hears so", {
    timeout: 60_000,
  }, async () => {
    const [version] = await researcherApi.versions.list.query({
      experimentId: (
        await researcherApi.experiments.list.query({
          studyId: (await researcherApi.studies.mine.query())[0]!.id,
        })
      )[0]!.id,
    });
    const trial = await wizardApi.trials.create.mutate({ versionId: version!.id });
    const wizard = await (await newContext(browser, app.url)).newPage();
    // Between the page and the runtime: the answer to one command is lost with its connection, as a
    // network drop would lose it after the runtime had carried the command out.
    const sent: Array<{ requestId?: string; retry?: boolean; type: string }> = [];
    const answers: Array<{ type: string; requestId?: string }> = [];
    let loseNextAck = false;
    await wizard.routeWebSocket(/.*/, (page) => {
      const runtime = page.connectToServer();
      page.onMessage((m) => {
        sent.push(JSON.parse(String(m)));
        runtime.send(m);
      });
      runtime.onMessage((m) => {
        const message = JSON.parse(String(m));
        if (loseNextAck && message.type === "ack") {
          loseNextAck = false;
          page.close();
          runtime.close();
          return;
        }
        answers.push(message);
        page.send(m);
      });
    });
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trial.id}`);
    await wizard.getByText("live", { exact: true }).waitFor();
    // A note for the log: a command the wizard may give before the trial starts (the demo's one robot is
    // still held by the rehearsal above).
    await wizard.getByLabel("Wizard note").fill("Noted once");
    loseNextAck = true;
    await wizard.getByRole("button", { name: "Add note" }).click();
    // The page reconnects at once (its "reconnecting" may come and go between two looks).

    // The page asked again by the same request id, and heard that it was done: the form is cleared for the next note.
    const command = sent.find((m) => m.type === "command" && !m.retry && JSON.stringify(m).includes("Noted once"));
    await expect
      .poll(() => sent.filter((m) => m.retry && m.requestId === command?.requestId).length, { timeout: 20_000 })
      .toBe(1);
    await expect.poll(() => answers.some((m) => m.type === "ack" && m.requestId === command?.requestId)).toBe(true);
    await expect.poll(() => wizard.getByLabel("Wizard note").inputValue()).toBe("");
    expect(await wizard.getByText("The connection dropped before the server confirmed this.").count()).toBe(0);
    // Carried out once: one note in the log.
    const events = await researcherApi.trials.events.query({ trialId: trial.id });
    expect(events.filter((e) => JSON.stringify(e).includes("Noted once"))).toHaveLength(1);
    await wizard.context().close();
  });

  it("tells the wizard at once when the robot bridge drops, and when it is back", async () => {
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const [version] = await researcher.versions.list.query({ experimentId: experiment!.id });
    const trial = await wizardApi.trials.create.mutate({ versionId: version!.id });
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trial.id}`);
    await wizard.getByText("robot connected").waitFor();
    // On a tablet held upright the controls stack, and nothing needs sideways scrolling.
    await wizard.setViewportSize({ width: 768, height: 1024 });
    await wizard.getByRole("button", { name: /Start trial/ }).waitFor();
    expect(await wizard.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth)).toBe(true);
    await screenshot(wizard, "wizard-tablet");
    const simulator = childPid(app, "simulator/main.ts");
    process.kill(simulator, "SIGKILL");
    // The bound: the wizard sees the failure within 2 seconds.
    await wizard.getByText(/robot disconnected/).waitFor({ timeout: 2000 });
    await screenshot(wizard, "robot-disconnected");
    await wizard.getByText("robot connected").waitFor({ timeout: 15_000 });
    await wizard.context().close();
  });

  it("shows the database as unavailable while it is frozen, beside the runtime and the robot as they are", async () => {
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const [version] = await researcher.versions.list.query({ experimentId: experiment!.id });
    const trial = await wizardApi.trials.create.mutate({ versionId: version!.id });
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trial.id}`);
    await wizard.getByText("robot connected").waitFor();
    const status = (what: string) => wizard.getByTestId(`${what}-status`).textContent();
    await expect.poll(() => status("database")).toBe("connected");
    await signalDatabase(app.dataDir, "SIGSTOP");
    try {
      // Asked every 5 s, and answered "unavailable" within 5 s of asking.
      await expect.poll(() => status("database"), { timeout: 30_000 }).toBe("unavailable");
      expect(await status("runtime")).toBe("live");
      expect(await status("robot")).toBe("connected");
    } finally {
      await signalDatabase(app.dataDir, "SIGCONT");
    }
    await expect.poll(() => status("database"), { timeout: 30_000 }).toBe("connected");
    await wizard.context().close();
  });
});
