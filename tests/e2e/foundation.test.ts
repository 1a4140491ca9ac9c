// A researcher sets up a study in a real Chromium; the server keeps an
// observer from editing it and a non-member from even seeing it.
import { existsSync, readFileSync } from "node:fs";
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { join, normalize } from "node:path";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { expectAccessible } from "../support/accessibility";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { Researcher } from "../support/researcher";

describe.sequential("the platform foundation, in the browser", () => {
  let app: RunningApp;
  let browser: Browser;
  let studyUrl = "";
  // HRIStudio's repository, served from the fixture while the plugin tests run.
  let repo: Server | undefined;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
    repo?.close();
  });

  it("lets each demo role sign in and shows their role", async () => {
    for (const role of ["admin", "researcher", "wizard", "observer"]) {
      const context = await newContext(browser, app.url);
      const page = await context.newPage();
      await signInAs(page, `${role}@demo.hristudio`, DEMO_PASSWORD);
      await expect.poll(() => page.getByTestId("current-user").textContent()).toBeTruthy();
      if (role === "admin") {
        await page.getByRole("link", { name: "Admin" }).click();
        await page.getByRole("heading", { name: "Accounts" }).waitFor();
        await screenshot(page, "admin-accounts");
      }
      await context.close();
    }
  });

  it("lets an administrator add a plugin repository with the trust they choose, sync it, and see every plugin it added told apart from ours", async () => {
    const fixture = join(import.meta.dirname, "..", "fixtures", "hristudio-plugins");
    repo = createServer((req, res) => {
      const file = join(fixture, normalize(req.url!).replace(/^(\.\.[/\\])+/, ""));
      existsSync(file) ? res.end(readFileSync(file)) : res.writeHead(404).end();
    });
    await new Promise<void>((ok) => repo!.listen(0, "127.0.0.1", ok));
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "admin@demo.hristudio", DEMO_PASSWORD);
    await page.goto("/admin/plugins");
    await page.getByLabel("Repository address").fill(`http://127.0.0.1:${(repo!.address() as AddressInfo).port}/`);
    await page.getByLabel("Trust").click();
    await page.getByRole("option", { name: /^Verified/ }).click();
    await page.getByRole("button", { name: "Add repository" }).click();
    await page.getByRole("button", { name: /^Sync / }).click();
    // All three of HRIStudio's plugins are added, its NAO6 beside our first-party one of the same robotId and version.
    const report = page.getByRole("region", { name: "What the last sync changed" });
    for (const added of [
      "nao6-ros2: added (version 3.0.0)",
      "turtlebot3-burger: added (version 2.0.0)",
      "turtlebot3-waffle: added (version 2.0.0)",
    ])
      await report.getByRole("listitem").filter({ hasText: added }).waitFor();
    await report
      .getByText(
        /^nao6-ros2 is also provided by nao6-ros2 3\.0\.0 from the first-party plugins \([0-9a-f]{12}\) with the same version, 3\.0\.0: both are kept, told apart by their source and hash/,
      )
      .waitFor();
    // The catalogue tells the two NAO6 documents apart, and says which one experiments run unless they choose.
    await page
      .getByRole("row", {
        name: /nao6-ros2\s*3\.0\.0\s*[0-9a-f]{12}.*the first-party plugins.*Run by experiments that have not chosen/,
      })
      .waitFor();
    await page
      .getByRole("row", {
        name: /nao6-ros2\s*3\.0\.0\s*[0-9a-f]{12}.*HRIStudio Official Robot Plugins.*Run only by experiments that choose it/,
      })
      .waitFor();
    await page.getByText("HRIStudio Official Robot Plugins", { exact: true }).waitFor();
    // Its repository.json says official; the administrator's choice stands.
    await page
      .getByRole("row", { name: /^HRIStudio Official Robot Plugins/ })
      .getByText("verified")
      .waitFor();
    await screenshot(page, "admin-plugins");
    await page.context().close();
  });

  it("lets a researcher choose which NAO6 document an experiment runs, named by source, version and short hash, and never swaps in another", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    // Named to sort after the demo's Interactive Storyteller, which later tests pick first.
    await new Researcher(page).createExperiment("Storyteller on HRIStudio's NAO6");
    const designerUrl = page.url();
    const choice = page.getByLabel("Plugin document");
    const chosen = () => choice.locator("option:checked").textContent();
    // Not chosen yet: the first-party document, said as such.
    await expect.poll(chosen).toMatch(/^the first-party plugins · 3\.0\.0 · [0-9a-f]{12}$/);
    const theirs = await choice.locator("option", { hasText: "HRIStudio Official Robot Plugins" }).textContent();
    expect(theirs).toMatch(/^the repository "HRIStudio Official Robot Plugins" · 3\.0\.0 · [0-9a-f]{12}$/);
    await choice.selectOption({ label: theirs! });
    await expect.poll(chosen).toBe(theirs);
    // Recorded on the experiment, not only on the page.
    await page.reload();
    await expect.poll(chosen).toBe(theirs);

    // Removed, the repository leaves the list (versions already published with it keep their pinned files)...
    const admin = await (await newContext(browser, app.url)).newPage();
    await signInAs(admin, "admin@demo.hristudio", DEMO_PASSWORD);
    await admin.goto("/admin/plugins");
    admin.once("dialog", (dialog) => void dialog.accept());
    await admin.getByRole("button", { name: "Remove: HRIStudio Official Robot Plugins" }).click();
    await admin.getByText("No repositories yet.").waitFor();
    await admin.context().close();
    // ...and the experiment that chose it is told, never given the first-party document in its place.
    await page.goto(designerUrl);
    await expect.poll(chosen).toBe("No longer installed from the source chosen: choose one");
    await page.context().close();
  });

  it("refuses a wrong password in plain language", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await page.goto("/sign-in");
    await page.getByLabel("Email").fill("researcher@demo.hristudio");
    await page.getByLabel("Password").fill("not-the-password");
    await page.getByRole("button", { name: "Sign in" }).click();
    await page.getByRole("alert").filter({ hasText: "That email and password do not match an account." }).waitFor();
    await screenshot(page, "sign-in");
    await page.context().close();
  });

  it("lets a researcher create a study and add an observer", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.getByRole("heading", { name: "Storytelling and memory (demo)" }).waitFor();
    await screenshot(page, "dashboard");
    await page.getByRole("button", { name: "New study", exact: true }).click();
    await page.getByLabel("Title").fill("Gesture and recall");
    await page.getByLabel("Description").fill("Do a robot's gestures help listeners remember?");
    await expectAccessible(page, "the New study dialog");
    await page.getByRole("button", { name: "Create study" }).click();
    await page.waitForURL(/\/studies\/[\w-]+$/);
    await page.getByRole("heading", { name: "Gesture and recall", level: 1 }).waitFor();
    studyUrl = page.url();
    await page.getByRole("tab", { name: "Members" }).click();
    await page.getByLabel("Member email").fill("observer@demo.hristudio");
    await page.getByLabel("Study role").selectOption("observer");
    await page.getByRole("button", { name: "Add member" }).click();
    await page.getByRole("cell", { name: "observer@demo.hristudio" }).waitFor();
    await screenshot(page, "study-members");
    // An unknown email is explained, not swallowed.
    await page.getByLabel("Member email").fill("nobody@example.org");
    await page.getByRole("button", { name: "Add member" }).click();
    await page.getByRole("alert").filter({ hasText: "No account uses nobody@example.org" }).waitFor();
    await page.context().close();
  });

  it("shows an observer the study read-only, and the server refuses their edits", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "observer@demo.hristudio", DEMO_PASSWORD);
    await page.goto(studyUrl);
    await page.getByRole("heading", { name: "Gesture and recall" }).waitFor();
    await page.getByText("About this study").waitFor();
    expect(await page.getByRole("button", { name: "Save changes" }).count()).toBe(0);
    await page.getByRole("tab", { name: "Members" }).click();
    await page.getByRole("cell", { name: "observer@demo.hristudio" }).waitFor();
    expect(await page.getByRole("button", { name: "Add member" }).count()).toBe(0);
    // Past the interface, straight at the API with the observer's own session.
    const studyId = studyUrl.split("/").pop()!;
    const status = await page.evaluate(async (id) => {
      const res = await fetch("/api/trpc/studies.update", {
        method: "POST",
        headers: { "content-type": "application/json" },
        body: JSON.stringify({ studyId: id, title: "Hijacked" }),
      });
      return (await res.json()).error?.data?.code as string;
    }, studyId);
    expect(status).toBe("FORBIDDEN");
    await page.context().close();
  });

  it("does not let a non-member see the study, not even that it exists", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "wizard@demo.hristudio", DEMO_PASSWORD);
    await page.getByRole("heading", { name: "Storytelling and memory (demo)" }).waitFor();
    expect(await page.getByRole("heading", { name: "Gesture and recall" }).count()).toBe(0);
    await page.goto(studyUrl);
    await page.getByRole("heading", { name: "Study not found" }).waitFor();
    expect(await page.content()).not.toContain("Gesture and recall");
    await page.context().close();
  });

  it("lets the owner declare conditions and assign participants by a balanced strategy", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.getByRole("link", { name: /Storytelling and memory/ }).click();
    await page.getByRole("tab", { name: "Conditions" }).click();
    await page.getByLabel("Assignment strategy").selectOption("balanced");
    await page.getByRole("button", { name: "Use this strategy" }).click();
    await page.getByText(/Seed for the audit/).waitFor();
    for (const name of ["Gestures", "No gestures"]) {
      await page.getByLabel("Condition name").fill(name);
      await page.getByLabel("Runs experiment").selectOption({ index: 1 });
      await page.getByRole("button", { name: "Add condition" }).click();
      await page.getByRole("cell", { name, exact: true }).waitFor();
    }
    await screenshot(page, "conditions");
    await page.getByRole("tab", { name: "Participants" }).click();
    for (const code of ["P001", "P002"]) await page.getByRole("button", { name: `Assign ${code}` }).click();
    await expect
      .poll(async () => (await page.getByRole("cell", { name: /^(Gestures|No gestures)$/ }).allTextContents()).sort())
      .toEqual(["Gestures", "No gestures"]);
    await page.context().close();
  });

  it("shows an administrator who changed what in the audit log, one area at a time", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "admin@demo.hristudio", DEMO_PASSWORD);
    await page.getByRole("link", { name: "Admin" }).click();
    await page.getByLabel(/^Name\*?$/).fill("Tia Temp");
    await page.getByLabel(/^Email\*?$/).fill("tia@example.org");
    await page.getByLabel("Initial password").fill("password-123");
    await page.getByLabel("System role", { exact: true }).selectOption("observer");
    await page.getByRole("button", { name: "Create account" }).click();
    await page.getByLabel("System role of Tia Temp").selectOption("wizard");
    await expect.poll(() => page.getByLabel("System role of Tia Temp").inputValue()).toBe("wizard");

    await page.getByRole("navigation", { name: "Administration" }).getByRole("link", { name: "Audit log" }).click();
    await page.getByRole("heading", { name: "Audit log" }).waitFor();
    const log = page.getByRole("table", { name: "Audit log" });
    // Newest first: the role change, by the administrator, about Tia, with the new role.
    const newest = log.getByRole("row").nth(1);
    await newest.getByText("changed an account's role").waitFor();
    for (const cell of ["Ada Admin", "Tia Temp"]) await newest.getByRole("cell", { name: cell, exact: true }).waitFor();
    await newest.getByText("wizard", { exact: true }).waitFor();
    // Earlier tests' study changes carry the study's title.
    await log
      .getByRole("row")
      .filter({ hasText: "added a member" })
      .filter({ hasText: "Gesture and recall" })
      .first()
      .waitFor();
    await screenshot(page, "admin-audit-log");

    await page.getByLabel("Show", { exact: true }).selectOption({ label: "Accounts" });
    await expect
      .poll(async () => (await log.getByRole("row").allTextContents()).slice(1).every((row) => /user\./.test(row)))
      .toBe(true);
    expect(
      await log.getByRole("row").filter({ hasText: "created an account" }).filter({ hasText: "Tia Temp" }).count(),
    ).toBe(1);
    await page.context().close();
  });

  it("lets the owner delete a study only by typing its title", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(studyUrl);
    await page.getByRole("button", { name: "Delete study…" }).click();
    const dialog = page.getByRole("dialog", { name: "Delete this study?" });
    const confirm = dialog.getByRole("button", { name: "Delete the study and all its data" });
    await dialog.getByLabel(/Type the study's title/).fill("Gesture and");
    expect(await confirm.isDisabled()).toBe(true);
    await dialog.getByLabel(/Type the study's title/).fill("Gesture and recall");
    await expectAccessible(page, "the Delete study dialog");
    await confirm.click();
    await page.waitForURL(/\/studies$/);
    await page.getByRole("link", { name: /Storytelling and memory/ }).waitFor();
    expect(await page.getByRole("link", { name: /Gesture and recall/ }).count()).toBe(0);
    await page.context().close();
  });

  it("sends a visitor without a session to the sign-in page", async () => {
    const page = await (await newContext(browser, app.url)).newPage();
    await page.goto(studyUrl);
    await page.waitForURL("**/sign-in");
    await page.context().close();
  });
});
