// bench/designer: an experiment of 100 steps and 1,000 actions in the real
// designer page in Chromium: the time until it is shown, and the time from a
// move (Alt+↓ on the selected action) until the timeline has changed and
// the browser painted. Target: a move under 50 ms.
// Takes about a minute (and the app's build first, once).
import { launchBrowser, newContext, signInAs } from "../tests/support/browser";
import { DEMO_PASSWORD, startApp } from "../tests/support/app";
import { apiClient, signIn } from "../tests/support/http";
import { report } from "./support";

const STEPS = 100;
const ACTIONS_PER_STEP = 10;
const MOVES = 200;
const RENDERS = 5;

const app = await startApp();
try {
  const api = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
  const [study] = await api.studies.mine.query();
  const experiment = await api.experiments.create.mutate({
    studyId: study!.id,
    name: "Large protocol",
    robotId: "nao6-ros2",
  });
  await api.experiments.saveDesign.mutate({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: Array.from({ length: STEPS }, (_, s) => ({
      name: `Step ${s + 1}`,
      description: "",
      actions: Array.from({ length: ACTIONS_PER_STEP }, (_, a) =>
        a % 2
          ? { type: "wave", name: "", parameters: {}, parallelGroup: null }
          : { type: "say", name: "", parameters: { text: `Line ${s + 1}.${a + 1}` }, parallelGroup: null },
      ),
    })),
  });

  const browser = await launchBrowser();
  const page = await (await newContext(browser, app.url)).newPage();
  await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
  const total = STEPS * ACTIONS_PER_STEP;

  const renders: number[] = [];
  for (let i = 0; i < RENDERS; i++) {
    const started = performance.now();
    await page.goto(`/experiments/${experiment.id}`);
    await page.waitForFunction((n) => document.querySelectorAll("[data-action]").length === n, total, {
      timeout: 60_000,
    });
    renders.push(performance.now() - started);
  }

  await page.locator('[data-step="Step 50"] [data-action]').first().click();
  const moves: number[] = [];
  for (let i = 0; i < MOVES; i++) {
    // Down through the step and on into the next, then back up: every move changes the DOM.
    const key = Math.floor(i / 15) % 2 ? "ArrowUp" : "ArrowDown";
    moves.push(
      await page.evaluate(
        (key) =>
          new Promise<number>((done) => {
            const list = document.querySelector('[aria-label="Protocol"]')!;
            const started = performance.now();
            const seen = new MutationObserver(() => {
              seen.disconnect();
              requestAnimationFrame(() => done(performance.now() - started));
            });
            seen.observe(list, { childList: true, subtree: true, attributes: true });
            window.dispatchEvent(new KeyboardEvent("keydown", { key, altKey: true, bubbles: true }));
          }),
        key,
      ),
    );
  }
  await browser.close();

  console.log(`An experiment of ${STEPS} steps and ${total} actions, in Chromium:`);
  report("open the designer until every action is shown (page load)", renders);
  report("move an action (Alt+arrow) until changed and painted", moves, 50);
} finally {
  await app.stop();
}
