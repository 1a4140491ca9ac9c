// Debian's Chromium driven by playwright-core, for end-to-end tests. Every
// page they reach is checked against WCAG 2.1 AA (./accessibility): the
// sign-in form, each screenshot, and each page as a test leaves it.
import { chromium, type Browser, type BrowserContext, type Page } from "playwright-core";
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { checkPagesOnClose, expectAccessible } from "./accessibility";
import { CHROMIUM_ARGS, findChromium } from "./chromium";
import { scratchRoot } from "./scratch";

const root = resolve(import.meta.dirname, "..", "..");

/**
 * Debian's Chromium, headless. `lowPriority` runs it, and every process it starts, at the lowest CPU
 * priority (nice 19, for its session too): a bench's stand-in for browsers on other computers, so that what it measures is
 * the server's own cost, not many browsers and the server sharing two cores.
 */
export async function launchBrowser({ lowPriority = false } = {}): Promise<Browser> {
  const found = findChromium();
  if (!found) throw new Error("Chromium not found: install Debian's chromium package or set HRI_CHROMIUM.");
  if (!lowPriority) return chromium.launch({ executablePath: found, args: CHROMIUM_ARGS, headless: true });
  const wrapper = mkdtempSync(join(tmpdir(), "hri-chromium-"));
  const executablePath = join(wrapper, "chromium");
  // Playwright starts the browser in a session of its own, and the kernel's autogroup scheduling shares
  // the CPU between sessions before it looks at nice: the session's own weight must be lowered too.
  writeFileSync(
    executablePath,
    `#!/bin/sh\necho 19 > /proc/self/autogroup 2>/dev/null\nexec nice -n 19 ${JSON.stringify(found)} "$@"\n`,
    { mode: 0o755 },
  );
  // Removed as the browser goes: a wrapper in the machine's temporary folder, one a run, was left behind.
  const browser = await chromium.launch({ executablePath, args: CHROMIUM_ARGS, headless: true }).catch((error) => {
    rmSync(wrapper, { recursive: true, force: true });
    throw error;
  });
  browser.on("disconnected", () => rmSync(wrapper, { recursive: true, force: true }));
  return browser;
}

/**
 * A browser context of its own (a person, a device); the default viewport is a laptop's. `touch` makes it a
 * phone or tablet: touch events, a coarse pointer, the page's own mobile viewport.
 */
export async function newContext(
  browser: Browser,
  baseURL: string,
  viewport = { width: 1366, height: 800 },
  { touch = false } = {},
): Promise<BrowserContext> {
  const context = await browser.newContext({ baseURL, viewport, hasTouch: touch, isMobile: touch });
  context.setDefaultTimeout(15_000);
  checkPagesOnClose(context);
  return context;
}

// The sign-in form is the same page every time: checked once per test file.
let signInChecked = false;

export async function signInAs(page: Page, email: string, password: string) {
  await page.goto("/sign-in");
  if (!signInChecked) {
    await page.getByLabel("Email").waitFor();
    await expectAccessible(page, "the sign-in form");
    signInChecked = true;
  }
  await page.getByLabel("Email").fill(email);
  await page.getByLabel("Password").fill(password);
  await page.getByRole("button", { name: "Sign in" }).click();
  await page.waitForURL((url) => !url.pathname.startsWith("/sign-in"));
}

/** Set to 1 (`npm run screenshots`), the browser tests refresh the screenshots committed under docs/. */
export const REFRESH_SCREENSHOTS = "HRI_REFRESH_SCREENSHOTS";

/**
 * Where screenshots go: the run's own folder, so that a test run leaves the committed docs as they are;
 * docs/screenshots when they are being refreshed on purpose.
 */
export function screenshotFolder(): string {
  return process.env[REFRESH_SCREENSHOTS] === "1"
    ? join(root, "docs", "screenshots")
    : join(scratchRoot(), "screenshots");
}

/** Screenshots the docs use, as <name>.png (see screenshotFolder). What they show is checked first. */
export async function screenshot(page: Page, name: string) {
  await expectAccessible(page, `screenshot ${name}`);
  const dir = screenshotFolder();
  mkdirSync(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`) });
}
