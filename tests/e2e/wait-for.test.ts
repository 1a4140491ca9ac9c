// A "Wait for" in a real Chromium, on the simulated robot: the wizard's page
// shows what is awaited, by the plugin's names, and the go on key; a head
// touch or a phrase fired from the simulated robot's Robot page moves a
// waiting trial along its edge; G moves it along the step's own way on,
// logged as the wizard's choice, not a deviation; G and a touch together move
// it once; a touch with nothing waiting is logged and changes nothing. The
// designer's rehearsal lets the touch happen too.
import { randomUUID } from "node:crypto";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { publishDemoDesign, say } from "../support/demo-design";
import { apiClient, signIn } from "../support/http";

/** A step that says one line, then ends the trial. */
const saying = (name: string, line: string) => ({
  name,
  description: "",
  after: { to: "end" as const },
  actions: [say(line)],
});

describe.sequential("a wait for the robot's senses in the wizard's page", () => {
  let app: RunningApp;
  let browser: Browser;
  let researcher: ReturnType<typeof apiClient>;
  let wizardApi: ReturnType<typeof apiClient>;
  let experimentId = "";
  let versionId = "";
  let studyId = "";
  let robot: Page;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const touched = randomUUID();
    const ready = randomUUID();
    // "Touch my head to start": head touched → Touched, 'ready' heard → Ready, the go on → Greet (the step's way on).
    const published = await publishDemoDesign(app.url, [
      {
        name: "Wait",
        description: "",
        actions: [
          {
            type: "wait_for",
            name: "",
            parameters: {
              events: [
                { id: "touch", event: "head_touched", after: { to: "step", stepId: touched } },
                { id: "ready", event: "heard_ready", after: { to: "step", stepId: ready } },
              ],
            },
            parallelGroup: null,
            timeLimit: { seconds: 600, after: { to: "end" } },
          },
        ],
      },
      { name: "Greet", description: "", after: { to: "end" }, actions: [say("Hello!")] },
      { ...saying("Touched", "You touched my head."), id: touched },
      { ...saying("Ready", "Let us begin."), id: ready },
    ]);
    ({ researcher, experimentId, versionId, studyId } = published);
    // The simulated robot's Robot page, open beside the wizard's all along, as a pilot's second window.
    robot = await (await newContext(browser, app.url)).newPage();
    await signInAs(robot, "researcher@demo.hristudio", DEMO_PASSWORD);
    await robot.goto("/robot");
    await senses().getByRole("button", { name: "Head touched", exact: true }).waitFor();
  }, 180_000);
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  const senses = () => robot.getByRole("region", { name: "What the robot senses" });
  const touchHead = () => senses().getByRole("button", { name: "Head touched", exact: true }).click();
  const log = async (trialId: string) => researcher.trials.events.query({ trialId });
  const count = async (trialId: string, type: string) => (await log(trialId)).filter((e) => e.type === type).length;

  /** A trial of the published version, started on the wizard's page: the wait is pending. */
  async function waitingTrial(n: number) {
    // A participant of its own: each consented, each run once.
    const participant = await researcher.participants.create.mutate({
      studyId,
      code: `W-${n}`,
      consentStatus: "given",
      consentDate: new Date(),
    });
    const trialId = (await wizardApi.trials.create.mutate({ versionId, participantId: participant.id })).id;
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("robot connected").waitFor();
    await wizard.getByRole("button", { name: /Start trial/ }).click();
    await expect.poll(() => wizard.getByTestId("current-step").textContent()).toBe("Wait");
    const panel = wizard.getByRole("region", { name: "Waiting for the robot" });
    await panel.waitFor();
    return { trialId, wizard, panel };
  }

  const step = (wizard: Page) => wizard.getByTestId("current-step").textContent();

  /** Ends the trial, so that the robot is free for the next. */
  async function complete(wizard: Page, trialId: string) {
    await wizard.getByRole("button", { name: "Complete trial" }).click();
    await expect.poll(() => count(trialId, "trial.completed")).toBe(1);
    await wizard.context().close();
  }

  it("shows what the trial waits for by the plugin's names, and the go on key moves it on", async () => {
    const { trialId, wizard, panel } = await waitingTrial(0);
    await expect.poll(() => panel.textContent()).toContain("Head touched → “Touched”");
    await expect.poll(() => panel.textContent()).toContain('Heard "ready" → “Ready”');
    await expect.poll(() => panel.textContent()).toContain("nothing in 600 s → the end of the trial");
    await wizard.getByText("Nothing sensed in").waitFor();
    await screenshot(wizard, "wizard-wait-for");
    await wizard.keyboard.press("g");
    await expect.poll(() => step(wizard)).toBe("Greet");
    await panel.waitFor({ state: "detached" });
    // The big button offers the next step's line again: the trial goes on as usual.
    await wizard.getByRole("button", { name: "N Say: Hello!", exact: true }).waitFor();
    await complete(wizard, trialId);
  });

  it("a head touch fired from the Robot page advances the waiting trial; a hand touched, with nothing waiting, is logged and changes nothing", async () => {
    const { trialId, wizard, panel } = await waitingTrial(1);
    await touchHead();
    await expect.poll(() => step(wizard), { timeout: 10_000 }).toBe("Touched");
    await panel.waitFor({ state: "detached" });
    expect((await log(trialId)).find((e) => e.type === "wait.resolved")).toMatchObject({
      by: "sensed",
      event: "head_touched",
    });
    await senses().getByRole("button", { name: "Left hand touched", exact: true }).click();
    await expect.poll(() => count(trialId, "robot.sensed"), { timeout: 10_000 }).toBe(2);
    expect((await log(trialId)).filter((e) => e.type === "robot.sensed").at(-1)).toMatchObject({
      event: "left_hand_touched",
    });
    expect(await count(trialId, "wait.resolved")).toBe(1);
    expect(await count(trialId, "step.entered")).toBe(2);
    expect(await step(wizard)).toBe("Touched");
    await complete(wizard, trialId);
  });

  it("a phrase typed on the Robot page advances another", async () => {
    const { trialId, wizard } = await waitingTrial(2);
    await senses().getByLabel("A phrase the robot hears").fill("ready");
    await senses().getByLabel("Confidence (0–1)").fill("0.9");
    await senses().getByRole("button", { name: "Hear it" }).click();
    await expect.poll(() => step(wizard), { timeout: 10_000 }).toBe("Ready");
    expect((await log(trialId)).find((e) => e.type === "robot.sensed")).toMatchObject({
      event: "heard_ready",
      message: { words: ["ready"], confidence_values: [0.9] },
    });
    await complete(wizard, trialId);
  });

  it("the wizard's go on and a touch together move the trial exactly once", async () => {
    const { trialId, wizard } = await waitingTrial(3);
    await Promise.all([wizard.keyboard.press("g"), touchHead()]);
    await expect.poll(() => count(trialId, "robot.sensed"), { timeout: 10_000 }).toBe(1);
    await expect.poll(() => step(wizard)).not.toBe("Wait");
    const entered = (await log(trialId)).filter((e) => e.type === "step.entered");
    expect(await count(trialId, "wait.resolved")).toBe(1);
    // Whichever came first: the start, then one way on.
    expect(entered).toHaveLength(2);
    expect(["Greet", "Touched"]).toContain(await step(wizard));
    await complete(wizard, trialId);
  });

  it("the designer's rehearsal lets the touch happen, and follows its edge", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/experiments/${experimentId}`);
    // The Wait for's properties: each event by the robot's name for it, with where it leads.
    await page.locator('[data-step="Wait"] [data-action]').first().click();
    await page.getByRole("region", { name: "Properties" }).getByText("Events the trial waits for").waitFor();
    await screenshot(page, "designer-wait-for");
    await page.getByRole("tab", { name: "Rehearse" }).click();
    const preview = page.getByRole("region", { name: "Rehearsal preview" });
    const steps = preview.getByRole("list", { name: "What the robot would do" });
    await expect.poll(() => steps.textContent()).toMatch(/1\. Wait[\s\S]*2\. Greet/);
    await preview.getByLabel(/^Wait: /).selectOption({ label: "The robot senses: Head touched" });
    await expect
      .poll(() => steps.textContent())
      .toMatch(/1\. Wait[\s\S]*The robot sensed: Head touched[\s\S]*3\. Touched[\s\S]*The trial ends\./);
    await page.context().close();
  });
});
