// Conditions in one experiment, in a real Chromium on the simulated robot: the
// Storyteller's greeting varies by condition (a warm and a plain telling). Two
// trials, one per condition, each run in the blinded wizard's page: the robot
// says each condition's own greeting, byte for byte as the variant's text; the
// wizard's page shows the greeting as it will run and never the condition's
// name; the trial's record names the variant it ran. A whole step's own
// actions, made in the designer, are saved, published and run in their condition.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { listenToSpeech } from "../support/robot-ears";
import { runToTheEndInPage, runWholeTrial } from "../support/run-trial";

// Text a variant must carry unchanged: quotes, a backslash, a line break and characters beyond ASCII.
const GREETINGS = {
  "Warm telling QX7": 'Hello, friend! "Kai" \\ the astronaut\nça va? 🤖 赤い',
  "Plain telling MW9": "Hello. This is a story about Kai.",
};

describe.sequential("an experiment whose conditions vary", () => {
  let app: RunningApp;
  let browser: Browser;
  const trials: Array<{ id: string; condition: keyof typeof GREETINGS }> = [];
  let greetingId = "";
  let studyId = "";
  let experimentId = "";
  const conditionIds: Record<string, string> = {};

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizard = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    studyId = study!.id;
    const [experiment] = await researcher.experiments.list.query({ studyId });
    experimentId = experiment!.id;
    const conditions = Object.keys(GREETINGS) as Array<keyof typeof GREETINGS>;
    const ids: string[] = [];
    for (const name of conditions) {
      ids.push((await researcher.conditions.create.mutate({ studyId, name, experimentId: experiment!.id })).id);
      conditionIds[name] = ids.at(-1)!;
    }
    await researcher.studies.update.mutate({
      studyId,
      settings: { assignment: { strategy: "fixed", perCondition: 1 }, blinding: { conditionsFromWizards: true } },
    });
    const draft = await researcher.experiments.get.query({ experimentId: experiment!.id });
    const [greeting] = draft.steps[0]!.actions;
    greetingId = greeting!.id;
    greeting!.variants = Object.fromEntries(
      Object.entries(GREETINGS).map(([condition, text]) => [
        condition,
        { parameters: { ...greeting!.parameters, text } },
      ]),
    );
    await researcher.experiments.saveDesign.mutate({
      experimentId: draft.id,
      baseRevision: draft.draftRevision,
      steps: draft.steps,
    });
    const versionId = (await researcher.versions.publish.mutate({ experimentId: experiment!.id })).id;
    const participants = await researcher.participants.list.query({ studyId });
    for (const [i, condition] of conditions.entries()) {
      const participantId = participants[i]!.id;
      await researcher.conditions.assign.mutate({ participantId, conditionId: ids[i] });
      trials.push({ id: (await wizard.trials.create.mutate({ versionId, participantId })).id, condition });
    }
  }, 900_000);
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("runs each trial's own variant, byte for byte, never naming its condition to the blinded wizard", async () => {
    const ears = await listenToSpeech(app.simulatorUrl);
    try {
      for (const { id, condition } of trials) {
        const wizard = await (await newContext(browser, app.url)).newPage();
        await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
        await wizard.goto(`/trials/${id}`);
        await wizard.getByText("live", { exact: true }).waitFor();
        await wizard.getByRole("button", { name: "Start trial" }).click();
        // The greeting as this trial will say it (its whole line a hover away), and no condition's name anywhere in the page.
        const line = wizard.getByTestId(`action-${greetingId}`).locator("span[title]");
        await expect.poll(() => line.getAttribute("title"), { timeout: 30_000 }).toBe(GREETINGS[condition]);
        const html = await wizard.content();
        for (const name of Object.keys(GREETINGS)) expect(html).not.toContain(name);
        await runToTheEndInPage(wizard);
        const heard = ears.take();
        expect(heard[0], `what the robot said first in "${condition}"`).toBe(GREETINGS[condition]);
        expect(heard).not.toContain(
          GREETINGS[condition === "Warm telling QX7" ? "Plain telling MW9" : "Warm telling QX7"],
        );
        await wizard.context().close();
      }
    } finally {
      ears.close();
    }

    // The researcher's record of each trial names the variant it ran.
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    for (const { id, condition } of trials) {
      const record = await (await researcher.request.get(`/api/trials/${id}/export?format=json`)).json();
      expect(record.protocol.steps[0].actions[0]).toMatchObject({
        variant: condition,
        parameters: { text: GREETINGS[condition] },
      });
    }
    await researcher.context().close();
  }, 600_000);

  it("saves a whole step's own actions made in the designer, publishes them and runs them in a trial of that condition", async () => {
    const plain = "Plain telling MW9";
    const own = 'Welcome. "Step" \\ variant for Plain.';
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/experiments/${experimentId}`);
    await page.getByRole("button", { name: /^Step 1: Introduction/ }).click();
    const properties = page.getByRole("region", { name: "Properties" });
    const column = properties.getByRole("group", { name: `In “${plain}”` });
    await column.getByRole("checkbox", { name: `Own actions in “${plain}”` }).check();
    const text = column.getByRole("textbox").first();
    await text.fill(own);
    await expect.poll(() => page.locator("[data-save-state]").getAttribute("data-save-state")).toBe("saved");
    // The whole field in view: the shared actions, the plain telling's own, and the warm telling's (wrapped below).
    await properties.getByRole("group", { name: "In “Warm telling QX7”" }).scrollIntoViewIfNeeded();
    await screenshot(page, "designer-step-variants");
    await page.context().close();

    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const saved = await researcher.experiments.get.query({ experimentId });
    const variant = saved.steps[0]!.variants?.[plain];
    expect(variant?.actions[0]?.parameters.text).toBe(own);
    // A copy of the step's actions, each another action (a new id), without the greeting's own variants.
    expect(variant?.actions.map((a) => a.id)).not.toContain(greetingId);
    expect(variant?.actions).toHaveLength(saved.steps[0]!.actions.length);

    const versionId = (await researcher.versions.publish.mutate({ experimentId })).id;
    const participant = await researcher.participants.create.mutate({
      studyId,
      code: "STEP-PLAIN",
      consentStatus: "given",
      consentDate: new Date(),
    });
    await researcher.conditions.assign.mutate({ participantId: participant.id, conditionId: conditionIds[plain] });
    const wizard = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const trialId = (await wizard.trials.create.mutate({ versionId, participantId: participant.id })).id;
    const ears = await listenToSpeech(app.simulatorUrl);
    try {
      await runWholeTrial(wizard, trialId);
      expect(ears.take()[0], "what the robot said first in the step's own actions").toBe(own);
    } finally {
      ears.close();
    }
  }, 600_000);

  it("shows each condition's variant side by side in the designer, says which condition has none, and rehearses as one", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    await researcher.conditions.create.mutate({ studyId, name: "Silent telling", experimentId });
    await page.goto(`/experiments/${experimentId}`);
    await page.locator('[data-step="Introduction"] [data-action]').first().click();
    const properties = page.getByRole("region", { name: "Properties" });
    await properties.getByText("Varies by condition", { exact: true }).waitFor();
    for (const [condition, text] of Object.entries(GREETINGS)) {
      const own = properties.getByRole("group", { name: `In “${condition}”` });
      expect(await own.getByRole("checkbox").isChecked()).toBe(true);
      // A one-line field, as the shared action's text is: it shows the line without its break.
      expect(await own.getByRole("textbox").inputValue()).toBe(text.replace("\n", ""));
    }
    const silent = properties.getByRole("group", { name: "In “Silent telling”" });
    expect(await silent.getByRole("checkbox").isChecked()).toBe(false);
    expect(await silent.textContent()).toContain("Runs the action as above.");
    await expect
      .poll(() => page.getByRole("region", { name: "Checks" }).textContent())
      .toContain('"Silent telling" has no variant of it and runs the shared one.');
    await screenshot(page, "designer-variants");

    // A rehearsal from the Experiments tab, as one condition: its trial runs that condition's variant.
    await page.goto(`/studies/${studyId}`);
    await page.getByRole("tab", { name: "Experiments" }).click();
    await page.getByLabel("Rehearse Interactive Storyteller as").selectOption("Warm telling QX7");
    await page.getByRole("button", { name: "Rehearse Interactive Storyteller" }).click();
    await page.waitForURL(/\/trials\//);
    await page.getByRole("button", { name: "Start trial" }).click();
    const line = page.getByTestId(`action-${greetingId}`).locator("span[title]");
    await expect.poll(() => line.getAttribute("title"), { timeout: 30_000 }).toBe(GREETINGS["Warm telling QX7"]);
    await page.context().close();
  }, 300_000);

  it("edits a step's own action's other settings in the designer, beside its main text", async () => {
    const plain = "Plain telling MW9";
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/experiments/${experimentId}`);
    await page.getByRole("button", { name: /^Step 3: Recall question/ }).click();
    const column = page.getByRole("region", { name: "Properties" }).getByRole("group", { name: `In “${plain}”` });
    await column.getByRole("checkbox", { name: `Own actions in “${plain}”` }).check();
    // The pause's length, folded under its "More settings": a condition that holds still for less.
    await column.getByLabel(/^More settings of Hold still, action 1/).click();
    await column.getByRole("spinbutton", { name: /Seconds/ }).fill("1");
    await expect.poll(() => page.locator("[data-save-state]").getAttribute("data-save-state")).toBe("saved");
    await page.context().close();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const saved = await researcher.experiments.get.query({ experimentId });
    const recall = saved.steps.find((s) => s.name === "Recall question")!;
    expect(recall.variants?.[plain]?.actions[0]).toMatchObject({ type: "pause", parameters: { seconds: 1 } });
    // The shared pause is as it was.
    expect(recall.actions[0]).toMatchObject({ type: "pause", parameters: { seconds: 2 } });
  }, 300_000);
});
