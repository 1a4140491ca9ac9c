// A "Wait for" in a real Chromium, on the simulated robot: the trial waits
// (here on a long time limit alone: the simulated robot's Robot page, which
// fires its senses, comes with the robot's senses), the wizard's page shows
// what is awaited and the go on key, and G moves the trial along the step's
// own way on, logged as the wizard's choice, not a deviation.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";

const say = (text: string) => ({ type: "say", name: "", parameters: { text }, parallelGroup: null });

describe.sequential("a wait for the robot's senses in the wizard's page", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const draft = await researcher.experiments.get.query({ experimentId: experiment!.id });
    await researcher.experiments.saveDesign.mutate({
      experimentId: draft.id,
      baseRevision: draft.draftRevision,
      steps: [
        {
          name: "Wait",
          description: "",
          actions: [
            {
              type: "wait_for",
              name: "",
              parameters: { events: [] },
              parallelGroup: null,
              timeLimit: { seconds: 600, after: { to: "end" } },
            },
          ],
        },
        { name: "Greet", description: "", after: { to: "end" }, actions: [say("Hello!")] },
      ],
    });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    trialId = (await wizardApi.trials.create.mutate({ versionId: version.id, participantId: participant!.id })).id;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("shows what the trial waits for, and the go on key moves it on", async () => {
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("robot connected").waitFor();
    await wizard.getByRole("button", { name: /Start trial/ }).click();
    await expect.poll(() => wizard.getByTestId("current-step").textContent()).toBe("Wait");
    const panel = wizard.getByRole("region", { name: "Waiting for the robot" });
    await panel.waitFor();
    await expect.poll(() => panel.textContent()).toContain("nothing in 600 s → the end of the trial");
    await wizard.getByText("Nothing sensed in").waitFor();
    await screenshot(wizard, "wizard-wait-for");
    await wizard.keyboard.press("g");
    await expect.poll(() => wizard.getByTestId("current-step").textContent()).toBe("Greet");
    await panel.waitFor({ state: "detached" });
    // The big button offers the next step's line again: the trial goes on as usual.
    await wizard.getByRole("button", { name: "N Say: Hello!", exact: true }).waitFor();
    await wizard.context().close();
  });
});
