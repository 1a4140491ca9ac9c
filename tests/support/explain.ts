// When a wait on the live system fails, the failure says what the system
// held: each trial's log, what each page showed, and the app's own output.
// A failure on a CI run can then be read without running it again.
import type { Page } from "playwright-core";
import type { RunningApp } from "./app";
import { DEMO_PASSWORD } from "./app";
import { apiClient, signIn } from "./http";

export async function explained<T>(
  wait: Promise<T>,
  what: { app: RunningApp; trialIds?: string[]; pages?: Page[] },
): Promise<T> {
  try {
    return await wait;
  } catch (error) {
    const lines: string[] = [];
    const reader = await signIn(what.app.url, "researcher@demo.hristudio", DEMO_PASSWORD)
      .then((cookie) => apiClient(what.app.url, cookie))
      .catch(() => null);
    for (const trialId of what.trialIds ?? []) {
      const log = await reader?.trials.events.query({ trialId }).catch((e: Error) => e.message);
      const brief = Array.isArray(log)
        ? log.map((e) => [e.seq, e.relMs, e.type, "actionId" in e ? e.actionId : "", "reason" in e ? e.reason : ""])
        : log;
      lines.push(`Trial ${trialId} log: ${JSON.stringify(brief)}`);
    }
    for (const [i, page] of (what.pages ?? []).entries())
      lines.push(
        `Page ${i} (${page.url()}): ${(
          await page
            .locator("main")
            .textContent()
            .catch(() => "")
        )?.slice(0, 2000)}`,
      );
    lines.push(`App output (last lines):\n${what.app.output().split("\n").slice(-60).join("\n")}`);
    (error as Error).message += `\n${lines.join("\n")}`;
    throw error;
  }
}
