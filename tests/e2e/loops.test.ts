// A bounded loop in a real Chromium, on the simulated robot: "ask again, at
// most twice, then say goodbye". The wizard runs the trial from their page;
// the step goes back twice, then its bound takes the trial on, and the
// analysis page counts the iterations. In the designer, the same loop is
// chosen from the step's "Then", drawn on the flow map and rehearsed.
import { randomUUID } from "node:crypto";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { expectAccessible } from "../support/accessibility";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { publishDemoDesign, say } from "../support/demo-design";
import { apiClient, signIn } from "../support/http";
import { Researcher } from "../support/researcher";

describe.sequential("a bounded loop on the wizard's page", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";
  let wizardApi: ReturnType<typeof apiClient>;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const ask = randomUUID();
    const { versionId, participantId } = await publishDemoDesign(app.url, [
      {
        id: ask,
        name: "Ask",
        description: "",
        after: { to: "again", stepId: ask, times: 2, onward: { to: "next" } },
        actions: [say("What color was I?")],
      },
      { name: "Bye", description: "", after: { to: "end" }, actions: [say("Goodbye.")] },
    ]);
    trialId = (await wizardApi.trials.create.mutate({ versionId, participantId })).id;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  /** Waits for the big button (named by its key, N) to offer `label`, then presses N. */
  const next = async (wizard: Page, label: string) => {
    await wizard.getByRole("button", { name: `N ${label}`, exact: true }).waitFor();
    await wizard.keyboard.press("n");
  };

  it("goes back twice, then its bound takes the trial on to the next step", async () => {
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("robot connected").waitFor();
    await wizard.getByRole("button", { name: /Start trial/ }).click();
    // Asked, then back to ask again, twice: the page says where the step leads each time.
    for (const [round, then] of ["Go to “Ask”", "Go to “Ask”", "Go to “Bye”"].entries()) {
      await next(wizard, "Say: What color was I?");
      // The docs' picture: asked again once, about to go back a second time.
      if (round === 1) await screenshot(wizard, "wizard-loop");
      await next(wizard, then);
    }
    await expect.poll(() => wizard.getByTestId("current-step").textContent()).toBe("Bye");
    await next(wizard, "Say: Goodbye.");
    await next(wizard, "Finish trial");
    await expect.poll(async () => (await wizardApi.trials.get.query({ trialId })).status).toBe("completed");
    await wizard.context().close();
  });

  it("counts the iterations on the analysis page, and names the loop as what moved the trial", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/trials/${trialId}/analysis`);
    const loops = page.getByRole("region", { name: "Loops" });
    await expect
      .poll(() => loops.getByRole("listitem").allTextContents())
      .toEqual([
        "From “Ask” back to “Ask”: went back 2 of at most 2 times; its bound was reached and the trial went on",
      ]);
    await expect(loops.getByText("Steps entered more than once: “Ask” 3 times.").count()).resolves.toBe(1);
    await screenshot(page, "analysis-loops");
    const path = page.getByRole("region", { name: "What moved the trial" });
    await expect
      .poll(() => path.getByRole("listitem").allTextContents())
      .toEqual([
        expect.stringMatching(/^Ask at .*: by the start$/),
        expect.stringMatching(/^Ask at .*: by the loop going back \(time 1\)$/),
        expect.stringMatching(/^Ask at .*: by the loop going back \(time 2\)$/),
        expect.stringMatching(/^Bye at .*: by a loop's bound \(2 times\) reached$/),
      ]);
    const trial = await wizardApi.trials.get.query({ trialId });
    expect(trial.status).toBe("completed");
    await expectAccessible(page, "the analysis page with a loop's iterations");
    await page.context().close();
  });

  it("is designed from the step's Then, drawn on the flow map with its bound, and rehearsed round to its bound", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    const r = new Researcher(page);
    await r.createExperiment("Ask again");
    await r.addStep("Ask");
    await r.say("Ask", "What color was I?");
    await r.addStep("Bye");
    await r.say("Bye", "Goodbye.");
    await r.click(page.getByRole("button", { name: /^Step 1: Ask/ }));
    await r.selectOption(
      r.properties.getByLabel("Then", { exact: true }),
      "Go back to this step, at most 2 times, then …",
    );
    expect(await r.properties.getByLabel("At most (times back)").inputValue()).toBe("2");
    await r.selectOption(r.properties.getByLabel("Then, after the last time"), "Go on to the next step (Bye)");
    await expectAccessible(page, "the designer with a loop's bound and its way on");
    await screenshot(page, "designer-loop");
    const checks = page.getByRole("region", { name: "Checks" });
    await expect.poll(() => checks.textContent()).toContain("Ready to publish");

    await r.click(page.getByRole("tab", { name: "Flow map" }));
    await page.getByRole("group", { name: "Flow map of the experiment" }).waitFor();
    await page.getByText("Ask (back, at most 2 times) leads to Ask").waitFor({ state: "attached" });
    await page.getByText("Ask (after 2 times) leads to Bye").waitFor({ state: "attached" });
    await screenshot(page, "designer-flow-map-loop");

    await r.click(page.getByRole("tab", { name: "Rehearse" }));
    const preview = page.getByRole("region", { name: "Rehearsal preview" });
    await expect
      .poll(() => preview.getByRole("list", { name: "What the robot would do" }).innerText())
      .toMatch(/1\. Ask[\s\S]*1\. Ask\s*back round the loop, time 1[\s\S]*time 2[\s\S]*2\. Bye[\s\S]*The trial ends\./);
    await page.context().close();
  });
});
