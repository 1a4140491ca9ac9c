// The analysis API as a researcher uses it: a token made on the Access tokens
// page of the real app, copied once, then given to the pandas example of
// docs/analysis-api.md, which is taken from the docs and run as written
// against the same running server. It reads a study's trials and events, is
// refused another study, and is refused once the token is revoked.
import { spawnSync } from "node:child_process";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { pythonEnvironment } from "../support/python";
import { connectTrial } from "../support/socket";

const DOCS = join(import.meta.dirname, "..", "..", "docs", "analysis-api.md");

/** The first ```python block of the docs: the example exactly as a reader copies it. */
function documentedExample(): string {
  const block = /```python\n([\s\S]*?)```/.exec(readFileSync(DOCS, "utf8"));
  if (!block) throw new Error("docs/analysis-api.md has no ```python example");
  return block[1]!;
}

describe.sequential("the analysis API from Python, with a token made in the browser", () => {
  let app: RunningApp;
  let browser: Browser;
  let studyId = "";
  let otherStudyId = "";
  let secret = "";

  function runExample(env: { HRI_TOKEN: string; HRI_STUDY: string }) {
    return spawnSync(pythonEnvironment(), ["-c", documentedExample()], {
      encoding: "utf8",
      timeout: 120_000,
      env: { ...process.env, HRI_URL: app.url, ...env },
    });
  }

  beforeAll(async () => {
    pythonEnvironment();
    app = await startApp();
    browser = await launchBrowser();
    // A trial of the demo study that has begun (its events are in the log), and a second study of the same researcher.
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    studyId = study!.id;
    const [experiment] = await researcher.experiments.list.query({ studyId });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId });
    const trial = await researcher.trials.create.mutate({ versionId: version.id, participantId: participant!.id });
    const { url, token } = await researcher.trials.socketToken.mutate({ trialId: trial.id });
    const socket = await connectTrial(url, token);
    expect(await socket.command("s1", { kind: "start" })).toMatchObject({ type: "ack" });
    socket.close();
    otherStudyId = (await researcher.studies.create.mutate({ title: "Pilot of another lab" })).id;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("makes a token for one study on the Access tokens page, shown once and copied", async () => {
    const context = await newContext(browser, app.url);
    await context.grantPermissions(["clipboard-read", "clipboard-write"]);
    const page = await context.newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.getByRole("link", { name: "Access tokens" }).click();
    await page.getByRole("heading", { name: "Access tokens" }).waitFor();
    await page.getByLabel("Name").fill("Nightly analysis in pandas");
    await page.getByLabel("Expires after (days)").fill("30");
    await page.getByLabel(/^Storytelling and memory \(demo\)/).check();
    await page.getByRole("button", { name: "Create token" }).click();
    secret = (await page.getByTestId("new-token").textContent())!;
    expect(secret).toMatch(/^hri_[A-Za-z0-9_-]{43}$/);
    await page.getByRole("button", { name: "Copy token" }).click();
    await page.getByRole("button", { name: "Copied" }).waitFor();
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(secret);
    const row = page.getByRole("row", { name: /Nightly analysis in pandas/ });
    await expect.poll(() => row.textContent()).toMatch(/Storytelling and memory \(demo\).*never.*active/);
    await screenshot(page, "access-tokens");
    // Shown once: after a reload the page has the token's name, never its secret.
    await page.reload();
    await row.waitFor();
    expect(await page.content()).not.toContain(secret);
    await context.close();
  });

  it("runs the documented pandas example: the study's trials and events", () => {
    const run = runExample({ HRI_TOKEN: secret, HRI_STUDY: studyId });
    expect(run.status, run.stderr).toBe(0);
    // participant, condition, status, events, deviations: the trial begun above, with its first events.
    expect(run.stdout).toMatch(/participant\s+condition\s+status\s+events\s+deviations/);
    expect(run.stdout).toMatch(/P00\d\s+NaN\s+in_progress\s+[1-9]\d*\s+0/);
  });

  it("is refused another study of the same researcher that the token was not made for", () => {
    const run = runExample({ HRI_TOKEN: secret, HRI_STUDY: otherStudyId });
    expect(run.status).not.toBe(0);
    expect(run.stderr).toMatch(/HTTPError: HTTP Error 404/);
  });

  it("is refused once the token is revoked on the page", async () => {
    const context = await newContext(browser, app.url);
    const page = await context.newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto("/account/tokens");
    const row = page.getByRole("row", { name: /Nightly analysis in pandas/ });
    // Its use above is on the list: last used is no longer "never".
    await expect.poll(() => row.textContent()).not.toMatch(/never/);
    await page.getByRole("button", { name: "Revoke Nightly analysis in pandas" }).click();
    await expect.poll(() => row.textContent()).toMatch(/revoked/);
    await context.close();
    const run = runExample({ HRI_TOKEN: secret, HRI_STUDY: studyId });
    expect(run.status).not.toBe(0);
    expect(run.stderr).toMatch(/HTTPError: HTTP Error 401/);
  });
});
