// What a team sets through the UI, and sees used: its own assignment seed
// (Conditions tab), a coding scheme's name (the scheme editor), and a neutral
// study name with its own consent words (Overview) on the participant's page.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";

const NEUTRAL = "A study of storytelling";
const AGREEMENT = "I have read the information sheet and agree";

describe.sequential("settings a team sets through the UI", () => {
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

  it("uses the seed, the scheme's name and the neutral name the researcher typed", async () => {
    const api = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await api.studies.mine.query();
    const studyId = study!.id;
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.getByRole("link", { name: /Storytelling and memory/ }).click();

    await researcher.getByLabel("Name shown to participants").fill(NEUTRAL);
    await researcher.getByLabel("Words beside the consent checkbox").fill(AGREEMENT);
    await researcher.getByRole("button", { name: "Save changes" }).click();
    await researcher.getByText("Saved.").waitFor();

    await researcher.getByRole("tab", { name: "Conditions" }).click();
    await researcher.getByLabel("Assignment strategy").selectOption("random");
    await researcher.getByLabel("Seed (optional)").fill("prereg-2026-11");
    await researcher.getByRole("button", { name: "Use this strategy" }).click();
    await researcher.getByText("prereg-2026-11", { exact: true }).waitFor();

    await researcher.getByRole("tab", { name: "Coding" }).click();
    await researcher.getByRole("button", { name: "Build a coding scheme" }).click();
    // The new scheme opens in the editor.
    await researcher.getByLabel("Scheme name").fill("Gaze coding (Lab B)");
    await researcher.getByRole("button", { name: "Save the scheme" }).click();
    await researcher.getByRole("cell", { name: "Gaze coding (Lab B)", exact: true }).waitFor();

    // The seed assigns: a participant's assignment records it.
    const [experiment] = await api.experiments.list.query({ studyId });
    await api.versions.publish.mutate({ experimentId: experiment!.id });
    await api.conditions.create.mutate({ studyId, name: "Only", experimentId: experiment!.id });
    const participant = await api.participants.create.mutate({
      studyId,
      code: "S-seed",
      consentStatus: "given",
      consentDate: new Date(),
    });
    const assigned = await api.conditions.assign.mutate({ participantId: participant.id });
    expect(assigned.assignment).toMatchObject({ seed: "prereg-2026-11" });
    expect((await api.coding.schemes.query({ studyId })).map((s) => s.name)).toContain("Gaze coding (Lab B)");

    // The participant's page: the neutral name and the study's consent words, never the title.
    const q = await api.questionnaires.create.mutate({ studyId, name: "Consent" });
    const draft = (await api.questionnaires.get.query({ questionnaireId: q.id })).draft;
    const items = [{ id: "consent", kind: "consent", text: "You may stop at any time.", required: true }];
    await api.questionnaires.save.mutate({
      questionnaireId: q.id,
      definition: { ...draft, sections: [{ ...draft.sections[0]!, items }] },
    });
    await api.questionnaires.publish.mutate({ questionnaireId: q.id });
    const { token } = await api.questionnaires.createLink.mutate({
      questionnaireId: q.id,
      participantId: participant.id,
    });
    const tablet = await (await newContext(browser, app.url)).newPage();
    await tablet.goto(`/q/${token}`);
    await tablet.getByText(NEUTRAL, { exact: true }).waitFor();
    await tablet.getByLabel(AGREEMENT).check();
    expect(await tablet.locator("body").textContent()).not.toContain(study!.title);
  }, 180_000);
});
