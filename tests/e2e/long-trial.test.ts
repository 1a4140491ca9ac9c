// The analysis of a long trial in a real Chromium: a protocol of 300 actions,
// each requested, dispatched and completed (900 events and more). The
// planned-versus-executed table and the events list draw only the rows in
// view, yet the keyboard reaches every row, and the table tells a screen
// reader how many rows it has and where each drawn one sits.
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { createDatabase } from "../../src/store/client";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, signInAs } from "../support/browser";
import { freshDatabaseUrl } from "../support/db";
import { publishDemoDesign } from "../support/demo-design";

const ACTIONS = 300;

describe.sequential("the analysis of a long trial", () => {
  let app: RunningApp;
  let browser: Browser;
  let database: ReturnType<typeof createDatabase>;
  let trialId = "";

  beforeAll(async () => {
    const url = await freshDatabaseUrl();
    app = await startApp({ env: { DATABASE_URL: url, HRI_SEED_DEMO: "true" } });
    database = createDatabase(url, { max: 2 });
    browser = await launchBrowser();
    const { researcher, versionId, participantId } = await publishDemoDesign(app.url, [
      {
        name: "A long story",
        description: "",
        actions: Array.from({ length: ACTIONS }, (_, i) => ({
          type: "say",
          name: `Line ${i + 1}`,
          parameters: { text: `Line ${i + 1}` },
          parallelGroup: null,
        })),
      },
    ]);
    trialId = (await researcher.trials.create.mutate({ versionId, participantId })).id;
    const [step] = (await researcher.trials.get.query({ trialId })).protocol.steps;

    // The log as the runtime writes it: the start, the step, every action in turn, the end; a second apart.
    const t0 = new Date(Date.now() - 3_600_000);
    const bodies = [
      { type: "trial.started" },
      { type: "step.entered", stepId: step!.id, via: "start" },
      ...step!.actions.flatMap((a) => [
        {
          type: "action.requested",
          stepId: step!.id,
          actionId: a.id,
          actionType: a.type,
          parameters: a.parameters,
          scripted: true,
        },
        { type: "action.dispatched", actionId: a.id },
        { type: "action.completed", actionId: a.id },
      ]),
      { type: "trial.completed" },
    ];
    const rows = bodies.map((body, i) => ({
      trial_id: trialId,
      seq: i + 1,
      type: body.type,
      server_time: new Date(t0.getTime() + i * 1000).toISOString(),
      rel_ms: i * 1000,
      actor_id: null,
      step_id: "stepId" in body ? body.stepId : null,
      action_id: "actionId" in body ? body.actionId : null,
      payload: JSON.stringify(body),
      deviation: false,
    }));
    const sql = database.db.$client;
    await sql`insert into trial_events ${sql(rows)}`;
    await sql`update trials set status = 'completed', t0 = ${t0.toISOString()}::timestamptz, ended_at = now() where id = ${trialId}`;
  }, 180_000);
  afterAll(async () => {
    await browser?.close();
    await database?.close();
    await app?.stop();
  });

  const open = async (): Promise<Page> => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/trials/${trialId}/analysis`);
    return page;
  };
  it("draws a window of the planned-versus-executed table, and the keyboard scrolls it to every row", async () => {
    const page = await open();
    const region = page.getByRole("region", { name: `Planned actions (${ACTIONS}); the arrow keys scroll them` });
    const table = region.getByRole("table");
    // Every row counted (the header and one per planned action), far fewer drawn.
    expect(await table.getAttribute("aria-rowcount")).toBe(String(ACTIONS + 1));
    await table.getByRole("row", { name: /Line 1\b.*executed/ }).waitFor();
    const rows = table.locator("tbody tr");
    expect(await rows.count()).toBeGreaterThan(0);
    expect(await rows.count()).toBeLessThan(100);
    expect(await table.getByRole("row", { name: /Line 300\b/ }).count()).toBe(0);

    // The region takes focus: End scrolls to the last action, Home back to the first.
    await region.focus();
    await page.keyboard.press("End");
    const last = table.getByRole("row", { name: /Line 300\b.*executed/ });
    await last.waitFor();
    expect(await last.getAttribute("aria-rowindex")).toBe(String(ACTIONS + 1));
    await expect.poll(() => last.isVisible()).toBe(true);
    expect(await table.getByRole("row", { name: /Line 1\b/ }).count()).toBe(0);
    expect(await rows.count()).toBeLessThan(100);
    await page.keyboard.press("Home");
    await table.getByRole("row", { name: /Line 1\b.*executed/ }).waitFor();

    // Page Down, again and again, passes every row in turn: none is skipped.
    const seen = new Set<number>();
    const see = async () => {
      for (const tr of await rows.evaluateAll((trs) => trs.map((tr) => tr.getAttribute("aria-rowindex"))))
        seen.add(Number(tr));
    };
    const scrolled = () => region.evaluate((box) => box.scrollTop);
    // At the bottom, or once three presses in a row moved it no further (a loaded machine may drop a scroll).
    const atBottom = () => region.evaluate((box) => box.scrollTop + box.clientHeight >= box.scrollHeight - 2);
    for (let still = 0; still < 3 && !(await atBottom()); ) {
      await see();
      const before = await scrolled();
      await page.keyboard.press("PageDown");
      const moved = await expect
        .poll(scrolled, { timeout: 3000 })
        .toBeGreaterThan(before)
        .then(
          () => true,
          () => false,
        );
      still = moved ? 0 : still + 1;
    }
    expect(await atBottom()).toBe(true);
    await expect.poll(() => last.isVisible()).toBe(true);
    await see();
    expect([...seen].sort((a, b) => a - b)).toEqual(Array.from({ length: ACTIONS }, (_, i) => i + 2));
    await page.context().close();
  }, 60_000);

  it("draws a window of the events list, and the arrow keys, Home and End reach every event", async () => {
    const page = await open();
    const events = ACTIONS * 3 + 3;
    const list = page.getByRole("group", { name: `Events and annotations (${events}); arrow keys move between them` });
    const first = list.getByRole("button", { name: /trial\.started/ });
    await first.waitFor();
    expect(await list.getByRole("button").count()).toBeLessThan(100);
    await first.focus();
    await page.keyboard.press("End");
    const end = list.getByRole("button", { name: /trial\.completed/ });
    await end.waitFor();
    await expect.poll(() => page.evaluate(() => document.activeElement?.textContent)).toContain("trial.completed");
    await page.keyboard.press("ArrowUp");
    await expect
      .poll(() => page.evaluate(() => document.activeElement?.textContent))
      .toMatch(/action\.completed.*Line 300/);
    await page.keyboard.press("Home");
    await expect.poll(() => page.evaluate(() => document.activeElement?.textContent)).toContain("trial.started");
    expect(await list.getByRole("button").count()).toBeLessThan(100);
    await page.context().close();
  }, 60_000);
});
