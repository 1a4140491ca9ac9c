// The newcomer's quiz, built as a researcher would in a real Chromium with the
// library, drag and drop and forms only: a question with three answers, one
// step per answer, all three rejoining a shared goodbye. The designer warns
// while the answers fall through into each other, the flow map and the
// rehearsal preview show the way through, and a rehearsal per answer makes
// the simulated robot say exactly that answer's path.
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { Researcher } from "../support/researcher";
import { listenToSpeech } from "../support/robot-ears";

const QUESTION = "Which planet is the red one?";
const ANSWERS = [
  ["Mars", "Right: Mars is the red planet."],
  ["Venus", "Not quite: Venus is the bright yellow one."],
  ["No answer", "Take your time. It is Mars."],
] as const;
const GOODBYE = "Thank you for playing. Goodbye!";
/** What the timeline says under each step once the answers rejoin Goodbye. */
const REJOINED = [
  "Then where the answer leads",
  'Then "Goodbye"',
  'Then "Goodbye"',
  'Then "Goodbye"',
  "Then the end of the trial",
];
const leadsTo = (page: Page) =>
  page.locator("[data-leads-to]").evaluateAll((ps) => ps.map((p) => p.textContent?.trim()));

describe.sequential("branches that rejoin, in the browser", () => {
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

  it("builds a three-way question whose answers rejoin Goodbye, and each rehearsal says only its answer's path", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    const r = new Researcher(page);
    await r.createExperiment("Planet quiz");
    await page.getByRole("region", { name: "Block library" }).waitFor();
    const studyUrl = new URL(
      (await page.getByRole("link", { name: "Back to the study" }).getAttribute("href"))!,
      app.url,
    ).href;

    await r.addStep("Question");
    await r.say("Question", QUESTION);
    await r.drag("record_answer", "Question");
    await r.fill(r.properties.getByLabel("Question for the wizard"), "What did the participant answer?");
    await r.fill(r.properties.getByLabel("Answer 1", { exact: true }), ANSWERS[0][0]);
    await r.fill(r.properties.getByLabel("Answer 2", { exact: true }), ANSWERS[1][0]);
    await r.click(r.properties.getByRole("button", { name: "Add an answer" }));
    await r.fill(r.properties.getByLabel("Answer 3", { exact: true }), ANSWERS[2][0]);
    await r.drag("branch", "Question");
    for (const [answer] of ANSWERS)
      await r.click(r.properties.getByRole("button", { name: `Create a new step for “${answer}”` }));
    for (const [answer, text] of ANSWERS) await r.say(`Response — ${answer}`, text);
    await r.addStep("Goodbye");
    await r.say("Goodbye", GOODBYE);

    // Built in list order, the answers' steps fall through into each other: the designer says so.
    const checks = page.getByRole("region", { name: "Checks" });
    await expect.poll(() => checks.textContent()).toContain("so both responses are given");
    await screenshot(page, "designer-fall-through");

    for (const [answer] of ANSWERS) {
      await r.click(page.getByRole("button", { name: new RegExp(`^Step \\d: Response — ${answer}`) }));
      await r.selectOption(r.properties.getByLabel("Then"), "Go to step 5: Goodbye");
    }
    await expect.poll(() => checks.textContent()).toContain("Ready to publish");
    await expect.poll(() => leadsTo(page)).toEqual(REJOINED);
    await screenshot(page, "designer-rejoin");

    await r.click(page.getByRole("tab", { name: "Flow map" }));
    const map = page.getByRole("group", { name: "Flow map of the experiment" });
    await map.waitFor();
    await screenshot(page, "designer-flow-map");

    await r.click(page.getByRole("tab", { name: "Rehearse" }));
    const preview = page.getByRole("region", { name: "Rehearsal preview" });
    await r.selectOption(preview.getByRole("combobox"), "Venus");
    await expect
      .poll(() => preview.getByRole("list", { name: "What the robot would do" }).innerText())
      // Numbered as the designer and the wizard's page number them: by place in the protocol, not visit order.
      .toMatch(/1\. Question[\s\S]*3\. Response — Venus[\s\S]*5\. Goodbye[\s\S]*The trial ends\./);
    expect(await preview.innerText()).not.toContain("Response — Mars");
    await screenshot(page, "designer-rehearsal-preview");

    await expect.poll(() => page.locator("[data-save-state]").getAttribute("data-save-state")).toBe("saved");
    await r.click(page.getByRole("button", { name: "Publish" }));
    await page.getByText(/Published version 1/).waitFor();
    console.log(`branching: built the three-way quiz in ${r.operations} UI operations`);

    const ears = await listenToSpeech(app.simulatorUrl);
    try {
      for (const [index, [answer, response]] of ANSWERS.entries()) {
        await rehearse(page, studyUrl, index + 1);
        expect(ears.take(), `what the robot said for "${answer}"`).toEqual([QUESTION, response, GOODBYE]);
      }
    } finally {
      ears.close();
    }

    // A copy to vary without touching the original: the same steps, rejoining the same way.
    await page.goto(studyUrl);
    await page.getByRole("tab", { name: "Experiments" }).click();
    await page.getByRole("button", { name: "Duplicate Planet quiz" }).click();
    // Into this study, the dialog's first choice.
    await page.getByRole("dialog").getByRole("button", { name: "Duplicate", exact: true }).click();
    await page.waitForURL(/\/experiments\//);
    await expect.poll(() => page.getByLabel("Experiment name").inputValue()).toBe("Planet quiz (copy)");
    await expect.poll(() => leadsTo(page)).toEqual(REJOINED);
    await page.context().close();
  }, 300_000);
});

/** A rehearsal from the Experiments tab, run from the keyboard, giving answer number `key` at the question. */
async function rehearse(page: Page, studyUrl: string, key: number) {
  await page.goto(studyUrl);
  await page.getByRole("tab", { name: "Experiments" }).click();
  await page.getByRole("button", { name: "Rehearse Planet quiz" }).click();
  await page.waitForURL(/\/trials\//);
  await page.getByText("live", { exact: true }).waitFor();
  const step = () => page.getByTestId("current-step").textContent();
  // N does what the big button says: each press waits until the page shows it, so no key meets a page still catching up.
  const next = async (label: string) => {
    await page
      .locator("button", { has: page.locator("kbd", { hasText: "N" }) })
      .filter({ hasText: label })
      .waitFor();
    await page.keyboard.press("n");
  };
  const spoken = async (text: string) => {
    // The wizard sees speech by its first words ("Say: Not quite: Venus is the…").
    await next(text.slice(0, 20));
    await page
      .getByTestId(/action-/)
      .filter({ hasText: text.slice(0, 20) })
      .getByText(/^done/)
      .waitFor();
  };
  await next("Start trial");
  await expect.poll(step).toBe("Question");
  await spoken(QUESTION);
  await page.getByText("What did the participant answer?").first().waitFor();
  await page.keyboard.press(String(key));
  const [answer, response] = ANSWERS[key - 1]!;
  await expect.poll(step).toBe(`Response — ${answer}`);
  await spoken(response);
  // Not the answer's sibling below it: the step where the answers meet.
  await next("Go to “Goodbye”");
  await expect.poll(step).toBe("Goodbye");
  await spoken(GOODBYE);
  await next("Finish trial");
  await expect.poll(() => page.getByTestId("trial-status").textContent()).toBe("completed");
}
