// A sound, a note and a description, from the study's Sounds tab to the
// wizard's ears: the researcher adds a WAV on the Sounds tab, an experiment on
// NAO6 (whose plugin cannot play a file) plays it, and in the trial the
// wizard reads the step's description and the action's note, and the wizard's
// browser plays the sound to its end, which ends the action in the log.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { expectAccessible } from "../support/accessibility";
import { silentWav } from "../support/audio";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";

describe.sequential("Play audio through the wizard's browser", () => {
  let app: RunningApp;
  let browser: Browser;
  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("is added on the Sounds tab, then played by the wizard's browser with the note and description shown", async () => {
    const researcherApi = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcherApi.studies.mine.query();

    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.goto(`/studies/${study!.id}`);
    await researcher.getByRole("tab", { name: "Sounds" }).click();
    await researcher
      .getByLabel("Add a sound file")
      .setInputFiles({ name: "chime.wav", mimeType: "audio/wav", buffer: Buffer.from(silentWav(3000)) });
    await researcher.getByRole("cell", { name: /^chime\.wav [0-9a-f]{12}$/ }).waitFor();
    await expect.poll(() => researcher.getByText("3.0 s").count()).toBe(1);
    await researcher
      .getByLabel("Add a sound file")
      .setInputFiles({ name: "notes.wav", mimeType: "audio/wav", buffer: Buffer.from("not a sound") });
    await researcher.getByRole("alert").getByText("“notes.wav” is not a WAV, MP3 or Ogg sound file").waitFor();
    await expectAccessible(researcher, "the Sounds tab");

    const [sound] = await researcherApi.audio.list.query({ studyId: study!.id });
    const experiment = await researcherApi.experiments.create.mutate({
      studyId: study!.id,
      name: "Chime",
      robotId: "nao6-ros2",
    });
    await researcherApi.experiments.saveDesign.mutate({
      experimentId: experiment.id,
      baseRevision: 0,
      steps: [
        {
          name: "Welcome",
          description: "The participant has just sat down.",
          actions: [
            {
              type: "play_audio",
              parameters: { fileId: sound!.id, name: sound!.name, sha256: sound!.sha256 },
              note: "Wait for the participant to look at the robot.",
            },
          ],
        },
      ],
    });
    const version = await researcherApi.versions.publish.mutate({ experimentId: experiment.id });
    const trial = await researcherApi.trials.rehearse.mutate({ experimentId: experiment.id });
    expect(version.snapshot.steps[0]!.actions[0]!.type).toBe("play_audio");

    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "researcher@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trial.id}`);
    await wizard.getByText("live", { exact: true }).waitFor();
    await wizard.keyboard.press("n");
    await wizard.getByTestId("step-description").getByText("The participant has just sat down.").waitFor();
    await wizard.getByTestId("action-note").getByText("Wait for the participant to look at the robot.").waitFor();
    await wizard.keyboard.press("n");
    await wizard.getByTestId("browser-sound").getByText("chime.wav").waitFor();
    await screenshot(wizard, "wizard-play-audio");
    await expect
      .poll(() => wizard.locator('[data-testid^="action-"]').first().textContent(), { timeout: 10_000 })
      .toMatch(/^done/);
    const log = await researcherApi.trials.events.query({ trialId: trial.id });
    const ends = log
      .filter((e) => "actionId" in e && e.type !== "action.requested")
      .map((e) => [e.type, "detail" in e ? e.detail : null]);
    expect(ends).toEqual([
      ["action.dispatched", { playedBy: "browser" }],
      ["action.completed", { playedBy: "browser" }],
    ]);
  });
});
