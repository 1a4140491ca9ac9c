// A question's time limit in a real Chromium, on the simulated robot: the
// wizard starts the trial and has the robot ask, then records nothing; the
// page counts the limit down and, when it runs out, the trial moves on to
// the limit's step by itself, logged as the protocol (no deviation). The
// designer shows the limit in the question's properties and on the flow map,
// and its rehearsal walks the limit's edge.
import { randomUUID } from "node:crypto";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { publishDemoDesign, say } from "../support/demo-design";
import { apiClient, signIn } from "../support/http";

describe.sequential("a time limit in the wizard's page", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";
  let experimentId = "";
  let wizardApi: ReturnType<typeof apiClient>;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const prompt = randomUUID();
    const published = await publishDemoDesign(app.url, [
      {
        name: "Ask",
        description: "",
        actions: [
          { type: "say", name: "", parameters: { text: "What color was I?" }, parallelGroup: null },
          {
            type: "record_answer",
            name: "",
            parameters: {
              options: [
                { id: "red", label: "red" },
                { id: "other", label: "other" },
              ],
            },
            parallelGroup: null,
            // Long enough for the page to be checked and photographed while it counts down.
            timeLimit: { seconds: 8, after: { to: "step", stepId: prompt } },
          },
        ],
      },
      { name: "Bye", description: "", after: { to: "end" }, actions: [say("Goodbye.")] },
      { id: prompt, name: "Prompt", description: "", after: { to: "end" }, actions: [say("Take your time.")] },
    ]);
    experimentId = published.experimentId;
    const { versionId, participantId } = published;
    trialId = (await wizardApi.trials.create.mutate({ versionId, participantId })).id;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("counts down, holds while paused, and moves the trial on to the limit's step when no answer comes", async () => {
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("robot connected").waitFor();
    await wizard.getByRole("button", { name: /Start trial/ }).click();
    await expect.poll(() => wizard.getByTestId("current-step").textContent()).toBe("Ask");
    await wizard.keyboard.press("n");
    // Once the robot has asked, the question's clock runs on the page.
    await wizard.getByText("No answer in").waitFor();
    await screenshot(wizard, "wizard-time-limit");
    // Paused, the clock stands still: the countdown holds until the wizard resumes.
    await wizard.getByRole("button", { name: "Pause (P)" }).click();
    await wizard.getByRole("button", { name: "Resume (P)" }).waitFor();
    const secondsLeft = async () => Number.parseInt((await wizard.getByTestId("time-left").textContent())!, 10);
    const held = await secondsLeft();
    await wizard.waitForTimeout(5_000);
    expect(await secondsLeft()).toBe(held);
    // Resumed, it goes on from what it had left: the 5 s paused are not counted (a page that
    // counted them would show at most held − 5, or none left; a few seconds' slack for a loaded machine).
    await wizard.getByRole("button", { name: "Resume (P)" }).click();
    await wizard.getByRole("button", { name: "Pause (P)" }).waitFor();
    await wizard.waitForTimeout(600);
    expect(await secondsLeft()).toBeGreaterThanOrEqual(held - 3);
    await expect.poll(() => wizard.getByTestId("current-step").textContent(), { timeout: 25_000 }).toBe("Prompt");
    const trial = await wizardApi.trials.get.query({ trialId });
    expect(trial.status).toBe("in_progress");
    await wizard.context().close();
  });

  it("shows the question's limit in the designer, its edge on the flow map and in a rehearsal", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/experiments/${experimentId}`);
    await page.locator('[data-action="Record answer"]').click();
    const properties = page.getByRole("region", { name: "Properties" });
    expect(await properties.getByLabel("No answer in (seconds)").inputValue()).toBe("8");
    await screenshot(page, "designer-time-limit");
    await page.getByRole("tab", { name: "Flow map" }).click();
    const map = page.getByRole("group", { name: "Flow map of the experiment" });
    await expect.poll(() => map.textContent()).toContain("8 s");
    await screenshot(page, "designer-flow-map-timeout");
    // The rehearsal walks the limit's edge when its time is let run out.
    await page.getByRole("tab", { name: "Rehearse" }).click();
    const preview = page.getByRole("region", { name: "Rehearsal preview" });
    await preview.getByRole("combobox").selectOption({ label: "No answer: let the time run out (8 s)" });
    await expect
      .poll(() => preview.getByRole("list", { name: "What the robot would do" }).innerText())
      .toMatch(/1\. Ask[\s\S]*No answer: its 8 s ran out\.[\s\S]*3\. Prompt[\s\S]*The trial ends\./);
    await page.context().close();
  });
});
