// A researcher attaches the SUS after the Storyteller; after a trial, the
// wizard opens the one-time link and the participant fills it in on a second
// device (a reload on the way loses nothing); the score appears on the
// analysis page and in the CSV export.
import { readFileSync } from "node:fs";
import { strFromU8, unzipSync } from "fflate";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { expectAccessible } from "../support/accessibility";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { runWholeTrial } from "../support/run-trial";

const ANSWERS = [4, 2, 3, 4, 3, 1, 3, 3, 3, 2];

describe.sequential("questionnaires in the browser", () => {
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

  it("attaches the SUS, has the participant fill it in after a trial, and shows the score", async () => {
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.getByRole("link", { name: /Storytelling and memory/ }).click();
    await researcher.getByRole("tab", { name: "Questionnaires" }).click();
    await researcher.getByRole("button", { name: "Add the System Usability Scale" }).click();
    await researcher.getByLabel("When System Usability Scale (SUS) is filled in").selectOption("after");
    await researcher.getByRole("button", { name: "Publish System Usability Scale (SUS)" }).click();
    await researcher.getByText("version 1", { exact: true }).waitFor();
    await screenshot(researcher, "questionnaires");

    // A Storyteller trial with P001, run to its end.
    const api = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await api.studies.mine.query();
    const [experiment] = await api.experiments.list.query({ studyId: study!.id });
    const version = await api.versions.publish.mutate({ experimentId: experiment!.id });
    const p001 = (await api.participants.list.query({ studyId: study!.id })).find((p) => p.code === "P001")!;
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const trial = await wizardApi.trials.create.mutate({ versionId: version.id, participantId: p001.id });
    await runWholeTrial(wizardApi, trial.id);

    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trial.id}`);
    await wizard.getByRole("button", { name: "Open System Usability Scale (SUS) for the participant" }).click();
    const link = (await wizard.getByTestId("questionnaire-link-System Usability Scale (SUS)").textContent())!.trim();
    // A tablet's camera reads it from the screen; or the page opens on this device.
    await wizard.getByTestId("link-qr").waitFor();
    expect(await wizard.getByRole("link", { name: "Open on this device" }).getAttribute("href")).toBe(link);
    await expectAccessible(wizard, "the questionnaire opened for the participant");
    expect(link).toMatch(/\/q\/[\w-]{20,}$/);

    // The participant's device: no account.
    const tablet = await (await newContext(browser, app.url, { width: 1024, height: 1366 })).newPage();
    await tablet.goto(link);
    const items = tablet.locator("fieldset");
    await expect.poll(() => items.count()).toBe(10);
    for (const [i, value] of ANSWERS.slice(0, 5).entries())
      await items
        .nth(i)
        .getByRole("radio", { name: new RegExp(`: ${value}$`) })
        .check();
    await tablet.getByText("Your answers so far are saved.").waitFor();
    await tablet.reload();
    await expect.poll(() => items.nth(4).getByRole("radio", { name: /: 3$/ }).isChecked()).toBe(true);
    for (const [i, value] of ANSWERS.entries())
      if (i >= 5)
        await items
          .nth(i)
          .getByRole("radio", { name: new RegExp(`: ${value}$`) })
          .check();
    await screenshot(tablet, "questionnaire-participant");
    await tablet.getByRole("button", { name: "Submit answers" }).click();
    await tablet.getByRole("heading", { name: "Thank you!" }).waitFor();
    await expectAccessible(tablet, "thanked for the answers");
    await tablet.goto(link);
    await tablet.getByText(/already been submitted with this link/).waitFor();
    await tablet.context().close();
    await wizard.context().close();

    await researcher.goto(`/trials/${trial.id}/analysis`);
    await expect.poll(() => researcher.getByTestId("questionnaire-score").textContent()).toBe("Score 60");
    await screenshot(researcher, "questionnaire-analysis");
    await researcher.goto(`/studies/${study!.id}`);
    await researcher.getByRole("tab", { name: "Trials" }).click();
    await researcher.getByRole("cell", { name: "System Usability Scale (SUS): 60" }).waitFor();
    const zipped = researcher.waitForEvent("download");
    await researcher.getByRole("button", { name: /Download the whole study/ }).click();
    const archive = unzipSync(readFileSync((await (await zipped).path())!));
    expect(strFromU8(archive["questionnaire-answers.csv"]!)).toMatch(
      new RegExp(
        `P001,[^,]*,${trial.id},System Usability Scale \\(SUS\\),System Usability Scale \\(SUS\\),1,score,,SUS score,,,60\r\n`,
      ),
    );
    expect(Object.keys(archive)).toContain(`trials/${trial.id}.eaf`);
    const csv = await (await researcher.request.get(`/api/studies/${study!.id}/questionnaires`)).text();
    expect(csv).toMatch(
      new RegExp(
        `P001,[^,]*,${trial.id},System Usability Scale \\(SUS\\),System Usability Scale \\(SUS\\),1,score,,SUS score,,,60\r\n`,
      ),
    );
    const record = JSON.parse((await api.trials.export.query({ trialId: trial.id, format: "json" })).body as string);
    expect(record.questionnaires).toMatchObject([
      { questionnaire: "System Usability Scale (SUS)", score: { score: 60 } },
    ]);
    await researcher.context().close();
  }, 180_000);

  it("builds a consent form, sends its link ahead, and the participant's agreement is their consent record", async () => {
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.getByRole("link", { name: /Storytelling and memory/ }).click();
    await researcher.getByRole("tab", { name: "Questionnaires" }).click();
    await researcher.getByRole("button", { name: "Build a questionnaire" }).click();
    await researcher.waitForURL(/\/questionnaires\//);
    await researcher.getByLabel("Name in the study").fill("Consent form");
    await researcher.getByLabel("Title the participant sees").fill("Taking part in the storytelling study");
    await researcher.getByLabel("Kind of question").selectOption("consent");
    await researcher.getByRole("button", { name: "Add question" }).click();
    await researcher
      .getByLabel("Text of question 1")
      .fill(
        "A robot will tell you a short story and ask you about it. We keep your answers under a code, never your name. You may stop at any time.",
      );
    await researcher.getByLabel("Kind of question").selectOption("number");
    await researcher.getByRole("button", { name: "Add question" }).click();
    await researcher.getByLabel("Text of question 2").fill("Your age (optional)");
    await screenshot(researcher, "questionnaire-builder");
    await researcher.getByRole("button", { name: "Publish" }).click();
    await researcher.getByText(/Published version 1/).waitFor();

    await researcher.getByRole("link", { name: "← Study" }).click();
    await researcher.getByRole("tab", { name: "Participants" }).click();
    // Typing before the page is interactive would be lost: its submit button says when it is.
    await expect
      .poll(() => researcher.getByRole("button", { name: "Add participant" }).isEnabled(), { timeout: 30_000 })
      .toBe(true);
    await researcher.getByLabel("Participant code").fill("C900");
    await researcher.getByRole("button", { name: "Add participant" }).click();
    await researcher.getByRole("cell", { name: "C900", exact: true }).waitFor({ timeout: 45_000 });
    await researcher.getByRole("button", { name: "Questionnaire link for C900" }).click();
    await researcher.getByLabel("Questionnaire", { exact: true }).selectOption({ label: "Consent form" });
    await researcher.getByRole("button", { name: "Make the link" }).click();
    const link = (await researcher.getByTestId("sent-link").textContent())!.trim();
    await expectAccessible(researcher, "the questionnaire link dialog");
    await researcher.keyboard.press("Escape");

    const phone = await (await newContext(browser, app.url, { width: 390, height: 844 })).newPage();
    await phone.goto(link);
    await phone.getByText("A robot will tell you a short story").waitFor();
    await phone.getByRole("button", { name: "Submit answers" }).click();
    await phone.getByText(/please agree to take part/).waitFor();
    await phone.getByLabel("I agree to take part").check();
    await phone.getByLabel("Your age (optional)").fill("34");
    await screenshot(phone, "questionnaire-consent");
    await phone.getByRole("button", { name: "Submit answers" }).click();
    await phone.getByRole("heading", { name: "Thank you!" }).waitFor();
    await phone.context().close();

    await researcher.reload();
    await researcher.getByRole("tab", { name: "Participants" }).click();
    await expect.poll(() => researcher.getByLabel("Consent of C900").inputValue()).toBe("given");
    await researcher.getByRole("cell", { name: "Consent form v1" }).waitFor();
    await researcher.context().close();
  }, 180_000);
});
