// The browser tests take the docs' screenshots, but a test run leaves the
// committed ones alone: they go under the run's own folder, and into
// docs/screenshots only when refreshing them is asked for (`npm run screenshots`).
import { existsSync } from "node:fs";
import { join, resolve } from "node:path";
import type { Browser } from "playwright-core";
import { afterAll, afterEach, beforeAll, describe, expect, it } from "vitest";
import { launchBrowser, REFRESH_SCREENSHOTS, screenshot, screenshotFolder } from "./browser";
import { scratchRoot } from "./scratch";

const docs = resolve(import.meta.dirname, "..", "..", "docs", "screenshots");

describe("screenshot", () => {
  let browser: Browser;
  const asked = process.env[REFRESH_SCREENSHOTS];
  beforeAll(async () => {
    browser = await launchBrowser();
  });
  afterAll(async () => browser?.close());
  afterEach(() => {
    if (asked === undefined) delete process.env[REFRESH_SCREENSHOTS];
    else process.env[REFRESH_SCREENSHOTS] = asked;
  });

  it("writes under the run's folder, never into docs/screenshots", async () => {
    delete process.env[REFRESH_SCREENSHOTS];
    const page = await browser.newPage();
    await page.setContent(
      `<!doctype html><html lang="en"><head><title>Shot</title></head><body><main><h1>Shot</h1></main></body></html>`,
    );
    await screenshot(page, "screenshot-helper-test");
    expect(existsSync(join(scratchRoot(), "screenshots", "screenshot-helper-test.png"))).toBe(true);
    expect(existsSync(join(docs, "screenshot-helper-test.png"))).toBe(false);
  });

  it("writes into docs/screenshots when they are being refreshed", () => {
    process.env[REFRESH_SCREENSHOTS] = "1";
    expect(screenshotFolder()).toBe(docs);
  });
});
