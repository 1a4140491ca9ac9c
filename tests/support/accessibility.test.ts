// The WCAG check the browser tests rely on: it finds what it should, under a
// page's own strict Content-Security-Policy, and says where and why.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { expectAccessible } from "./accessibility";
import { launchBrowser } from "./browser";

const PAGES: Record<string, string> = {
  "/clean": `<main><h1>Consent</h1><label>Your age <input></label><button>Submit answers</button></main>`,
  "/faulty": `<main><h1>Trial</h1><p class="faint">Step 1</p><button aria-label="Run Story now">run now</button><input></main>`,
};

describe("expectAccessible", () => {
  let server: Server;
  let browser: Browser;
  let page: Page;
  let base = "";

  beforeAll(async () => {
    server = createServer((req, res) => {
      // As strict as the app's: no inline script or style, so axe-core must arrive another way.
      res.setHeader("Content-Security-Policy", "default-src 'self'");
      if (req.url === "/style.css") return res.end(".faint { color: #90a1b9; background: #ffffff; }");
      res.setHeader("content-type", "text/html");
      res.end(
        `<!doctype html><html lang="en"><head><title>t</title><link rel="stylesheet" href="/style.css"></head><body>${PAGES[req.url!]}</body></html>`,
      );
    });
    await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
    base = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
    browser = await launchBrowser();
    page = await browser.newPage();
  });
  afterAll(async () => {
    await browser?.close();
    server?.close();
  });

  it("passes a page that meets WCAG 2.1 AA", async () => {
    await page.goto(`${base}/clean`);
    await expectAccessible(page);
  });

  it("fails a page that does not, naming each element's rule, impact, selector and fix", async () => {
    await page.goto(`${base}/faulty`);
    const message = await expectAccessible(page, "the wizard's view").then(
      () => "no failure",
      (e: Error) => e.message,
    );
    const lines = message.split("\n");
    expect(lines[0]).toBe("/faulty (the wizard's view) fails WCAG 2.1 AA:");
    expect(lines.slice(1).sort()).toEqual([
      expect.stringMatching(/^- color-contrast \[serious\] p: .*contrast of 2\.63/),
      expect.stringMatching(/^- label \[critical\] input: .*label/),
      expect.stringMatching(/^- label-content-name-mismatch \[serious\] button: .*not included in the accessible name/),
    ]);
  });
});
