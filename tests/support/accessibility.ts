// WCAG 2.1 AA in the browser tests: axe-core (from npm) is injected into the
// page as it is and asked for the WCAG 2.0 and 2.1 rules of levels A and AA.
// Nothing is switched off: a violation fails the test with a list a person can
// act on (rule, impact, element, what to fix).
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import type { AxeResults } from "axe-core";
import type { BrowserContext, Page } from "playwright-core";

const AXE_SOURCE = readFileSync(createRequire(import.meta.url).resolve("axe-core/axe.min.js"), "utf8");
const WCAG_21_AA = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"];

type Violations = AxeResults["violations"];

/** Runs axe-core on the page as it is now and fails, listing each violation, unless there are none. */
export async function expectAccessible(page: Page, what = "") {
  const violations = await axeViolations(page);
  if (violations.length === 0) return;
  const where = `${new URL(page.url()).pathname}${what ? ` (${what})` : ""}`;
  throw new Error(`${where} fails WCAG 2.1 AA:\n${describeViolations(violations)}`);
}

/** Each page a test leaves open is checked, as the test left it, when its context is closed. */
export function checkPagesOnClose(context: BrowserContext) {
  const close = context.close.bind(context);
  context.close = async (options) => {
    for (const page of context.pages())
      if (page.url().startsWith("http")) await expectAccessible(page, "as the test left it");
    return close(options);
  };
}

async function axeViolations(page: Page): Promise<Violations> {
  // Judged once the page has loaded and named itself: Next.js streams a page's title after its first
  // paint, and a page caught before that is not yet the page a person reads. A title that never comes
  // is still reported, by axe, below.
  await page.waitForLoadState("load").catch(() => {});
  await page.waitForFunction(() => document.title !== "", undefined, { timeout: 5000 }).catch(() => {});
  // Evaluated through the DevTools protocol, not a <script>: the page's Content-Security-Policy stays as served.
  if (!(await page.evaluate(() => "axe" in window))) await page.evaluate(AXE_SOURCE);
  return page.evaluate(async (tags) => {
    const axe = (window as unknown as { axe: typeof import("axe-core") }).axe;
    // Colours are judged as they settle: a control changing state mid-transition shows neither its old nor its new look.
    for (const animation of document.getAnimations())
      if (animation.effect?.getTiming().iterations !== Infinity) animation.finish();
    const results = await axe.run(document, { runOnly: { type: "tag", values: tags }, resultTypes: ["violations"] });
    return results.violations;
  }, WCAG_21_AA);
}

/** One line per failing element: rule id, impact, its selector, and axe's summary of what to fix. */
function describeViolations(violations: Violations): string {
  return violations
    .flatMap((v) =>
      v.nodes.map((node) => {
        const summary = (node.failureSummary ?? v.help).replace(/\s*\n\s*/g, " ");
        return `- ${v.id} [${node.impact ?? v.impact ?? "unknown"}] ${node.target.join(" ")}: ${summary}`;
      }),
    )
    .join("\n");
}
