// Answers as data, in a real Chromium: two quiz trials of the Storyteller on
// the simulated robot, one per condition, each recording another answer. The
// analysis page shows the answer beside its question and what moved the
// trial into each step; the ELAN file, read back by pympi, has the answer's
// value on its tier; the Results tab counts each answer per condition.
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { expectAccessible } from "../support/accessibility";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { pythonEnvironment, runPython } from "../support/python";
import { runWholeTrial } from "../support/run-trial";
import { scratchFolder } from "../support/scratch";

const RIGHT = "correct (red)";
const WRONG = "incorrect / don't know";

describe.sequential("the participant's answers as data", () => {
  let app: RunningApp;
  let browser: Browser;
  let studyId = "";
  const trialIds: string[] = [];

  beforeAll(async () => {
    pythonEnvironment();
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizard = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    studyId = study!.id;
    const [experiment] = await researcher.experiments.list.query({ studyId });
    const versionId = (await researcher.versions.publish.mutate({ experimentId: experiment!.id })).id;
    const [first, second] = await researcher.participants.list.query({ studyId });
    // Each participant in a condition of their own, each giving another answer.
    for (const [participant, condition, answer] of [
      [first!, "praise", 0],
      [second!, "neutral", 1],
    ] as const) {
      const { id: conditionId } = await researcher.conditions.create.mutate({
        studyId,
        name: condition,
        experimentId: experiment!.id,
      });
      await researcher.conditions.assign.mutate({ participantId: participant.id, conditionId });
      const trialId = (await wizard.trials.create.mutate({ versionId, participantId: participant.id })).id;
      await runWholeTrial(wizard, trialId, { answer });
      trialIds.push(trialId);
    }
  }, 900_000);
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("shows the answer on the analysis page and in ELAN, and counts the answers per condition on the Results tab", async () => {
    const context = await newContext(browser, app.url);
    const page = await context.newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);

    await page.goto(`/trials/${trialIds[0]}/analysis`);
    const planned = page.getByRole("region", { name: /Planned actions/ });
    await expect.poll(() => planned.locator("[data-answer]").allTextContents()).toEqual([`answered “${RIGHT}”`]);
    const path = page.getByRole("region", { name: "What moved the trial" });
    await expect
      .poll(() => path.getByRole("listitem").allTextContents())
      .toEqual([
        expect.stringMatching(/^Introduction at .*: by the start$/),
        expect.stringMatching(/^Story at .*: by the wizard's next$/),
        expect.stringMatching(/^Recall question at .*: by the wizard's next$/),
        expect.stringMatching(
          new RegExp(`^Response — correct at .*: by the answer “${RIGHT.replace(/[()]/g, "\\$&")}”$`),
        ),
      ]);
    await expectAccessible(page, "with the answer and what moved the trial");

    // The ELAN file as the page downloads it, read back by pympi: the answer's value on its tier.
    const eaf = await page.request.get(`/api/trials/${trialIds[0]}/export?format=eaf`);
    expect(eaf.status()).toBe(200);
    const file = join(scratchFolder("answers-"), "quiz.eaf");
    writeFileSync(file, await eaf.text());
    const { tiers } = JSON.parse(runPython("read_eaf.py", [file])) as {
      tiers: Record<string, Array<[number, number, string]>>;
    };
    expect(tiers.Answer!.map((a) => a[2])).toEqual([RIGHT]);

    await page.goto(`/studies/${studyId}`);
    await page.getByRole("tab", { name: "Results" }).click();
    const counts = page.getByRole("table", { name: "Answers to “Participant's answer” per condition" });
    const rows = () =>
      counts
        .getByRole("row")
        .evaluateAll((trs) => trs.map((tr) => [...tr.querySelectorAll("th, td")].map((c) => c.textContent?.trim())));
    await expect.poll(rows, { timeout: 30_000 }).toEqual([
      ["Answer", "neutral", "praise"],
      [RIGHT, "0", "1"],
      [WRONG, "1", "0"],
    ]);
    // Closing the context checks the Results tab, as left, for WCAG 2.1 AA too.
    await context.close();
  }, 300_000);
});
