// The study's pages on a tablet and a phone, in a real Chromium emulating a
// touch screen (375 × 812, a coarse pointer): the wizard's every control is a
// finger's size (44 px), the observer's page fits the screen and codes by a
// tap, and the times shown carry their zone, to be matched against the UTC
// of the exports.
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";

const PHONE = { width: 375, height: 812 };
// A zone as the browser writes it after a time: "UTC", "GMT+1", "CET", "PST".
const ZONE = /\d(:\d\d)?( [AP]M)? (UTC|GMT([+-]\d+)?|[A-Z]{3,5})/;

describe.sequential("touch screens and phones", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";
  let wizard: Page;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    trialId = (await wizardApi.trials.create.mutate({ versionId: version.id, participantId: participant!.id })).id;
    const scheme = await researcher.coding.createScheme.mutate({
      studyId: study!.id,
      template: "participant-engagement",
    });
    await researcher.coding.publishScheme.mutate({ codingSchemeId: scheme.id });
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  const phonePage = async (email: string) => {
    const page = await (await newContext(browser, app.url, PHONE, { touch: true })).newPage();
    await signInAs(page, email, DEMO_PASSWORD);
    return page;
  };

  /** What on the page is wider than the screen: the document, and the elements that make it so. */
  const overflow = (page: Page) =>
    page.evaluate(() => {
      const width = document.documentElement.clientWidth;
      const wide = [...document.querySelectorAll("body *")]
        .filter((e) => e.getBoundingClientRect().right > width + 1)
        .slice(0, 5)
        .map((e) => `${e.tagName.toLowerCase()}.${e.className}`.slice(0, 120));
      return { width: document.documentElement.scrollWidth, wide };
    });

  it("gives the wizard controls at least 44 px high on a touch screen", async () => {
    wizard = await phonePage("wizard@demo.hristudio");
    await wizard.goto(`/trials/${trialId}`);
    expect(await wizard.evaluate(() => matchMedia("(pointer: coarse)").matches)).toBe(true);
    await wizard.getByText("live", { exact: true }).waitFor();
    await wizard.getByRole("button", { name: "Start trial" }).tap();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent(), { timeout: 30_000 }).toBe("in progress");
    // The folded controls opened, so that what they hold is measured too.
    await wizard.getByText("Jump to another step (a deviation)").tap();
    await wizard
      .getByRole("button", { name: /^Jump to / })
      .first()
      .waitFor();
    for (const name of ["Skip (S)", "Pause (P)", "Emergency stop (Esc)"])
      await wizard.getByRole("button", { name }).waitFor();
    const small = await wizard.locator("main").evaluate((main) =>
      [...main.querySelectorAll("button, summary, input, select")]
        .map((e) => ({
          what: (e.textContent || e.getAttribute("aria-label") || "").trim(),
          box: e.getBoundingClientRect(),
        }))
        .filter(({ box }) => box.width > 0 && box.height < 44 && box.height > 0)
        .map(({ what, box }) => `${what} (${Math.round(box.height)} px)`),
    );
    expect(small).toEqual([]);
  }, 240_000);

  it("fits the observer's page on a phone, and codes what they tap", async () => {
    const observer = await phonePage("observer@demo.hristudio");
    // The dashboard's "Live now": the trial's start, with its zone.
    await observer.goto("/studies");
    const live = observer.getByRole("region", { name: "Live now" });
    await expect.poll(() => live.textContent(), { timeout: 30_000 }).toMatch(new RegExp(`started .*${ZONE.source}`));
    await live.getByRole("link", { name: "Watch" }).tap();
    await observer.waitForURL(`**/trials/${trialId}`);
    const marked = observer.getByText(/^\d+ codes? marked/);
    await marked.waitFor({ timeout: 30_000 });
    const fits = await overflow(observer);
    expect(fits.wide).toEqual([]);
    expect(fits.width).toBeLessThanOrEqual(PHONE.width);
    // A tap marks a code as its key would; a state tapped is held, lit.
    await observer.getByRole("button", { name: /At the robot/ }).tap();
    await expect.poll(() => marked.textContent()).toBe("1 code marked; last: At the robot");
    await observer.locator("li[data-held]").filter({ hasText: "At the robot" }).waitFor();
    await observer.getByRole("button", { name: /Smile/ }).tap();
    await expect.poll(() => marked.textContent()).toBe("2 codes marked; last: Smile");
    await observer.context().close();
  }, 240_000);

  it("shows the trial's start with its zone on the analysis page", async () => {
    await wizard.getByRole("button", { name: "Complete trial" }).tap();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent(), { timeout: 30_000 }).toBe("completed");
    await wizard.context().close();
    const page = await phonePage("researcher@demo.hristudio");
    await page.goto(`/trials/${trialId}/analysis`);
    await expect.poll(() => page.getByTestId("trial-started").textContent(), { timeout: 30_000 }).toMatch(ZONE);
    await page.context().close();
  }, 240_000);
});
