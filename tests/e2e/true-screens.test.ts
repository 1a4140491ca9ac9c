// Screens that must say what is true, as a research team found them wrong: a
// wizard offered Start on another wizard's session, a red "robot disconnected"
// after a normal end, and a finished trial reopened as "scheduled" with a live
// Start button and an analysis link the wizard may not use.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { runToTheEndInPage } from "../support/run-trial";

describe.sequential("screens that say what is true", () => {
  let app: RunningApp;
  let browser: Browser;
  let studyId = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    studyId = study!.id;
    const [storyteller] = await researcher.experiments.list.query({ studyId });
    await researcher.versions.publish.mutate({ experimentId: storyteller!.id });
    const told = await researcher.conditions.create.mutate({
      studyId,
      name: "Told",
      description: "",
      experimentId: storyteller!.id,
    });
    const members = await researcher.members.list.query({ studyId });
    const wizardOf = { P001: "wizard", P002: "owner" } as const;
    for (const [code, role] of Object.entries(wizardOf)) {
      const [participant] = (await researcher.participants.list.query({ studyId })).filter((p) => p.code === code);
      await researcher.conditions.assign.mutate({ participantId: participant!.id, conditionId: told.id });
      await researcher.sessions.schedule.mutate({
        participantId: participant!.id,
        plannedAt: new Date(),
        wizardId: members.find((m) => m.role === role)!.userId,
      });
    }
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("offers a wizard Start on their own sessions only, and shows their finished trial as finished", async () => {
    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`${app.url}/studies/${studyId}`);
    await wizard.getByRole("tab", { name: "Sessions" }).click();
    await wizard.getByRole("cell", { name: "P002" }).waitFor();
    // The researcher's session is theirs to run: no button the server would refuse.
    expect(await wizard.getByRole("button", { name: "Start the session of P002" }).count()).toBe(0);
    await wizard.getByRole("button", { name: "Start the session of P001" }).click();
    await wizard.waitForURL(/\/trials\//);
    const trialUrl = wizard.url();

    await runToTheEndInPage(wizard);
    // The trial let its robot go on purpose: no alarm.
    await expect.poll(() => wizard.getByTestId("robot-status").textContent()).toBe("released");

    // Opened again: a wizard may not read a finished trial's log, and the page says it has ended.
    await wizard.goto(trialUrl);
    await wizard.getByTestId("trial-ended").waitFor();
    expect(await wizard.getByTestId("trial-status").textContent()).toBe("completed");
    expect(await wizard.getByRole("button", { name: "Start trial" }).count()).toBe(0);
    expect(await wizard.getByRole("link", { name: /Open the analysis/ }).count()).toBe(0);
  });
});
