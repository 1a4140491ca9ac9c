// A researcher builds the Interactive Storyteller from an empty experiment in
// a real Chromium, using only the library, drag and drop and the properties
// forms; publishes it; exports it; the exported file scores 100 on the
// protocol's design checklist. Two researchers on one draft are told.
import { readFileSync } from "node:fs";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { Researcher } from "../support/researcher";
import { scoreDesign } from "../support/storyteller-design-checklist";
import { STORYTELLER_TEXT as TEXT } from "../support/storyteller-run-checklist";

describe.sequential("the experiment designer, in the browser", () => {
  let app: RunningApp;
  let browser: Browser;
  let designerUrl = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("builds the Interactive Storyteller from nothing, publishes and exports it, and the file scores 100", async () => {
    const context = await newContext(browser, app.url);
    const page = await context.newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    const r = new Researcher(page);

    await r.createExperiment("Storyteller, built by hand");
    designerUrl = page.url();
    await page.getByRole("region", { name: "Block library" }).waitFor();
    await screenshot(page, "designer-empty");

    await r.addStep("Introduction");
    await r.say("Introduction", TEXT.intro);
    await r.gestureWithSpeech("Introduction", "wave");

    await r.addStep("Story");
    await r.say("Story", TEXT.story);
    // This time with the library's "Run together", dropped on the step: its last action joins the one above.
    await r.drag("look_down", "Story");
    await r.drag("run_together", "Story");
    await expect.poll(() => r.properties.getByLabel("Starts together with the action above").isChecked()).toBe(true);

    await r.addStep("Recall question");
    await r.drag("pause", "Recall question");
    await r.fill(r.properties.getByLabel("Seconds"), "2");
    await r.say("Recall question", TEXT.question);
    await r.drag("record_answer", "Recall question");
    await r.fill(r.properties.getByLabel("Question for the wizard"), "What did the participant answer?");
    await r.fill(r.properties.getByLabel("Answer 1", { exact: true }), "correct (red)");
    await r.fill(r.properties.getByLabel("Answer 2", { exact: true }), "incorrect / don't know");
    // A question waits for the wizard's choice: it never starts together with the action above.
    expect(await r.properties.getByLabel("Starts together with the action above").count()).toBe(0);
    await r.drag("branch", "Recall question");
    expect(await r.properties.getByLabel("Starts together with the action above").count()).toBe(0);
    await expect
      .poll(() => page.getByRole("region", { name: "Checks" }).textContent())
      .toContain('choose the step the answer "correct (red)" leads to');
    await r.click(r.properties.getByRole("button", { name: "Create a new step for “correct (red)”" }));
    await r.click(r.properties.getByRole("button", { name: "Create a new step for “incorrect / don't know”" }));
    await screenshot(page, "designer-branch");

    for (const [answer, text, gesture] of [
      ["correct (red)", TEXT.correct, "nod"],
      ["incorrect / don't know", TEXT.incorrect, "head_shake"],
    ] as const) {
      const step = `Response — ${answer}`;
      await r.click(page.getByRole("button", { name: new RegExp(`^Step \\d: ${step.replace(/[()/]/g, ".")}`) }));
      await r.say(step, text);
      await r.gestureWithSpeech(step, gesture);
      await r.drag("end_trial", step);
    }
    // The last step: going on from it ends the trial, so "End the trial" is offered once.
    await r.click(page.getByRole("button", { name: /^Step 5: Response/ }).first());
    const then = await r.properties.getByLabel("Then").locator("option").allTextContents();
    expect(then.filter((o) => o.startsWith("End the trial"))).toEqual(["End the trial (last step)"]);

    const checks = page.getByRole("region", { name: "Checks" });
    await expect.poll(() => checks.textContent()).toContain("Ready to publish");
    await expect.poll(() => page.locator("[data-save-state]").getAttribute("data-save-state")).toBe("saved");
    await screenshot(page, "designer-storyteller");

    await r.click(page.getByRole("button", { name: "Publish" }));
    await page.getByText(/Published version 1/).waitFor();
    const download = page.waitForEvent("download");
    await r.click(page.getByRole("button", { name: "Export file" }));
    const file = readFileSync((await (await download).path())!, "utf8");
    await screenshot(page, "designer-published");

    // The methods text of the published version: every fact a paper needs, copied exactly as shown.
    await context.grantPermissions(["clipboard-read", "clipboard-write"]);
    await page.getByRole("button", { name: "Methods text", exact: true }).click();
    const methods = page.getByRole("region", { name: "Methods text" });
    await methods.waitFor();
    const shown = (await methods.textContent())!;
    for (const fact of [
      `The robot said “${TEXT.intro}” at the same time as it performed`,
      "There was a pause of 2 seconds.",
      "“correct (red)” led to “Response — correct (red)”",
      "The trial ended here.",
      "The version's SHA-256 hash is ",
    ])
      expect(shown).toContain(fact);
    await screenshot(page, "designer-methods-text");
    await page.getByRole("button", { name: "Copy as plain text" }).click();
    await page.getByText("Copied as plain text.").waitFor();
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(shown);
    await page.keyboard.press("Escape");

    // Speech and gesture start together in every step that has both.
    const steps = JSON.parse(file).steps as Array<{ actions: Array<{ type: string; runTogether?: string }> }>;
    for (const i of [0, 1, 3, 4]) {
      const [speech, gesture] = steps[i]!.actions;
      expect(speech!.runTogether).toBeTruthy();
      expect(gesture!.runTogether).toBe(speech!.runTogether);
    }
    const { score, failed } = scoreDesign(file);
    console.log(
      `designer: built the Interactive Storyteller in ${r.operations} UI operations; design checklist score ${score}/100`,
    );
    expect(failed).toEqual([]);
    expect(score).toBe(100);
    await context.close();
  }, 180_000);

  it("moves and undoes with the keyboard alone", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(designerUrl);
    const intro = page.locator('[data-step="Introduction"] [data-action]');
    await expect.poll(() => intro.count()).toBe(2);
    // The keys work once the page knows the researcher may edit: the library shows it.
    await page.getByRole("region", { name: "Block library" }).waitFor();
    await page.locator('[data-step="Introduction"] [data-action]').nth(1).focus();
    await page.keyboard.press("Enter");
    await page.keyboard.press("Alt+ArrowUp");
    await expect.poll(() => intro.first().getAttribute("data-action")).toBe("Wave");
    await page.keyboard.press("Control+z");
    await expect.poll(() => intro.first().getAttribute("data-action")).toBe("Say");
    await page.locator('[data-block="nod"]').focus();
    await page.keyboard.press("Enter");
    await expect.poll(() => intro.count()).toBe(3);
    // "Run together" from the library makes the selected nod start with the action above it.
    const together = page
      .getByRole("region", { name: "Properties" })
      .getByLabel("Starts together with the action above");
    expect(await together.isChecked()).toBe(false);
    await page.locator('[data-block="run_together"]').focus();
    await page.keyboard.press("Enter");
    await expect.poll(() => together.isChecked()).toBe(true);
    await page.keyboard.press("Control+z");
    await expect.poll(() => together.isChecked()).toBe(false);
    await page.keyboard.press("Control+z");
    await expect.poll(() => intro.count()).toBe(2);
    await page.context().close();
  }, 60_000);

  it("shows what another robot cannot do when the robot is switched, and lets an observer read but not edit", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(designerUrl);
    const checks = page.getByRole("region", { name: "Checks" });
    await expect.poll(() => checks.textContent()).toContain("can run on NAO6");
    await page.getByLabel("Robot", { exact: true }).selectOption({ label: "TurtleBot3 Burger" });
    await expect.poll(() => checks.textContent()).toMatch(/\d+ of \d+ actions cannot run on TurtleBot3 Burger/);
    await expect.poll(() => checks.textContent()).toMatch(/"Say" cannot run on TurtleBot3 Burger/i);
    await screenshot(page, "designer-portability");
    await page.getByRole("button", { name: "Undo" }).click();
    await expect.poll(() => checks.textContent()).toContain("can run on NAO6");
    // The undone robot is saved before the page closes: the later tests read this draft on NAO6.
    await expect.poll(() => page.locator("[data-save-state]").getAttribute("data-save-state")).toBe("saved");
    await page.context().close();

    const observer = await (await newContext(browser, app.url)).newPage();
    await signInAs(observer, "observer@demo.hristudio", DEMO_PASSWORD);
    await observer.goto(designerUrl);
    await observer.getByText("You can read this experiment").waitFor();
    await observer.getByRole("button", { name: /^Step 1:/ }).click();
    await expect
      .poll(() => observer.getByRole("region", { name: "Properties" }).getByLabel("Step name").isDisabled())
      .toBe(true);
    expect(await observer.getByRole("button", { name: "Publish" }).count()).toBe(0);
    await observer.context().close();
  }, 60_000);

  it("tells a researcher when someone else saved the same draft, and overwrites nothing silently", async () => {
    const pages = await Promise.all(
      ["researcher@demo.hristudio", "researcher@demo.hristudio"].map(async (email) => {
        const page = await (await newContext(browser, app.url)).newPage();
        await signInAs(page, email, DEMO_PASSWORD);
        await page.goto(designerUrl);
        await page.getByRole("list", { name: "Protocol" }).waitFor();
        return page;
      }),
    );
    const [first, second] = pages as [Page, Page];
    for (const [page, name] of [
      [first, "Introduction (first)"],
      [second, "Introduction (second)"],
    ] as const) {
      await page.getByRole("button", { name: /^Step 1:/ }).click();
      await page.getByRole("region", { name: "Properties" }).getByLabel("Step name").fill(name);
      if (page === first)
        await expect.poll(() => first.locator("[data-save-state]").getAttribute("data-save-state")).toBe("saved");
    }
    await second.getByText("Someone else saved this experiment while you were editing it.").waitFor();
    await screenshot(second, "designer-conflict");
    await second.getByRole("button", { name: /Load their version/ }).click();
    await expect
      .poll(() => second.getByRole("button", { name: /^Step 1:/ }).textContent())
      .toContain("Introduction (first)");
    await Promise.all(pages.map((p) => p.context().close()));
  }, 60_000);
  it("offers each capability once, takes drops below the last step and at the window's edge, and publishes only a changed draft", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(designerUrl);
    const library = page.getByRole("region", { name: "Block library" });
    await library.waitFor();
    const r = new Researcher(page);
    const actions = page.getByRole("list", { name: "Protocol" }).locator("[data-action]");
    // The designer's own <main> (inside the app's), the column that scrolls.
    const timeline = page.locator("main", { has: page.getByRole("list", { name: "Protocol" }) }).last();
    await expect.poll(() => actions.count()).toBeGreaterThan(0);

    // The draft was changed since version 1: publishing is offered, then refused as a copy.
    const publish = page.getByRole("button", { name: "Publish" });
    await expect.poll(() => publish.isEnabled()).toBe(true);
    await publish.click();
    await page.getByText(/Published version 2/).waitFor();
    await expect.poll(() => publish.isDisabled()).toBe(true);
    await page.getByText("Published as version 2; change the draft to publish again.").waitFor();

    // One "Stop", one "Nod": NAO6's own "Yes (Nod)" is a variant shown under Nod.
    const shown = async (name: string) =>
      (await library.locator("[data-block]").allTextContents()).filter((t) => t.toLowerCase() === name).length;
    expect(await shown("stop")).toBe(1);
    expect(await shown("look down")).toBe(1);
    expect(await shown("yes (nod)")).toBe(0);
    await library.getByRole("button", { name: /^1 version of Nod on NAO6/ }).click();
    expect(await shown("yes (nod)")).toBe(1);
    const lastStep = (await page.locator("[data-step]").last().getAttribute("data-step"))!;
    const inLast = page.locator(`[data-step="${lastStep}"] [data-action]`);
    const before = await inLast.count();
    await r.drag("nao6-ros2.play_animation_yes", lastStep);
    await expect.poll(() => inLast.last().getAttribute("data-action")).toBe("Yes (Nod)");
    await expect.poll(() => publish.isEnabled()).toBe(true);

    // Below the last step, on no step at all: the block goes at the end of the last step.
    const end = page.locator('[data-drop-zone="(end of the timeline)"]');
    const nod = library.locator('[data-block="nod"]');
    await nod.evaluate((el) => el.scrollIntoView({ block: "center" }));
    await end.evaluate((el) => el.scrollIntoView({ block: "end" }));
    let s = (await nod.boundingBox())!;
    const e = (await end.boundingBox())!;
    await page.mouse.move(s.x + s.width / 2, s.y + s.height / 2);
    await page.mouse.down();
    await page.mouse.move(s.x + s.width / 2 + 12, s.y + s.height / 2, { steps: 3 });
    await page.mouse.move(e.x + e.width / 2, e.y + e.height - 8, { steps: 12 });
    await page.mouse.up();
    await expect.poll(() => inLast.count()).toBe(before + 2);
    await expect.poll(() => inLast.last().getAttribute("data-action")).toBe("Nod");
    await page.waitForTimeout(100);

    // At the window's bottom edge, under the timeline scrolled to its top: the
    // timeline scrolls while the block is held there, and the drop adds it.
    await timeline.evaluate((el) => el.scrollTo(0, 0));
    const total = await actions.count();
    const column = (await timeline.boundingBox())!;
    const height = await page.evaluate(() => window.innerHeight);
    s = (await nod.boundingBox())!;
    await page.mouse.move(s.x + s.width / 2, s.y + s.height / 2);
    await page.mouse.down();
    await page.mouse.move(s.x + s.width / 2 + 12, s.y + s.height / 2, { steps: 3 });
    await page.mouse.move(column.x + column.width / 2, height - 4, { steps: 12 });
    await expect.poll(() => timeline.evaluate((el) => el.scrollTop)).toBeGreaterThan(0);
    await page.mouse.up();
    await expect.poll(() => actions.count()).toBe(total + 1);
    await screenshot(page, "designer-library-variants");
    await page.context().close();
  }, 90_000);
});
