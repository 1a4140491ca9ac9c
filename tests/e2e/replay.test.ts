// Replay in a real Chromium: after a finished Storyteller trial, the
// researcher presses Replay (×2) on its analysis page, and the robot page, open
// beside it, says the simulated robot is replaying that trial, not running a
// live one, while the robot speaks the trial's words again; Stop ends it.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { listenToSpeech } from "../support/robot-ears";
import { runWholeTrial } from "../support/run-trial";

describe.sequential("replaying a finished trial", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizard = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const versionId = (await researcher.versions.publish.mutate({ experimentId: experiment!.id })).id;
    const participantId = (await researcher.participants.list.query({ studyId: study!.id }))[0]!.id;
    trialId = (await wizard.trials.create.mutate({ versionId, participantId })).id;
    // Slow enough that the replay, even at ×2, is still going while the test looks at it.
    await runWholeTrial(wizard, trialId, { pauseMs: 2000 });
  }, 180_000);
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("the analysis page's Replay makes the robot page show the replay, of this trial, until it is stopped", async () => {
    const context = await newContext(browser, app.url);
    const analysis = await context.newPage();
    await signInAs(analysis, "researcher@demo.hristudio", DEMO_PASSWORD);
    await analysis.goto(`/trials/${trialId}/analysis`);
    const robot = await context.newPage();
    await robot.goto("/robot");
    await robot.getByText("connected", { exact: true }).waitFor();
    const ears = await listenToSpeech(app.simulatorUrl);

    await analysis.getByRole("button", { name: "×2" }).click();
    await analysis.getByRole("button", { name: "Replay from 0.0 s" }).click();
    await analysis.getByText(/Replaying from 0\.0 s at ×2/).waitFor();
    const banner = robot.getByRole("status", { name: "Replay" });
    await expect.poll(() => banner.textContent(), { timeout: 10_000 }).toMatch(/Replay, not live.*×2/);
    // Named for a member of the study, with the way to its analysis.
    await banner.getByRole("link", { name: /Interactive Storyteller/ }).waitFor();
    await expect.poll(() => ears.heard.length, { timeout: 15_000 }).toBeGreaterThan(0);
    await screenshot(robot, "robot-replay");
    await screenshot(analysis, "analysis-replay");

    await analysis.getByRole("button", { name: "Stop replay" }).click();
    await analysis.getByText("Replay stopped.").waitFor();
    await expect.poll(() => banner.textContent()).toMatch(/has ended/);
    ears.close();
  });
});
