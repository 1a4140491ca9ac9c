// Running a whole study in Chromium: a researcher sets up two conditions with
// balanced assignment, registers four consenting participants and plans their
// sessions; a blinded wizard runs all four from "My sessions" and never sees
// which condition a session was. Then a new study starts from this one as a
// template, and an experiment is copied back into it.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { runToTheEndInPage as runToTheEnd } from "../support/run-trial";

const CONDITIONS = ["Told with gestures", "Told by voice only"];
const CODES = ["S101", "S102", "S103", "S104"];

describe.sequential("a study with conditions, sessions and a blinded wizard", () => {
  let app: RunningApp;
  let browser: Browser;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    // Two published experiments to bind the conditions to: the demo Storyteller and a copy of it.
    const api = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await api.studies.mine.query();
    const [storyteller] = await api.experiments.list.query({ studyId: study!.id });
    const file = await api.experiments.exportFile.query({ experimentId: storyteller!.id });
    const copy = await api.experiments.importFile.mutate({
      studyId: study!.id,
      text: file.text.replace('"name": "Interactive Storyteller"', '"name": "Storyteller, voice only"'),
    });
    for (const id of [storyteller!.id, copy.id]) await api.versions.publish.mutate({ experimentId: id });
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("lets a researcher set it up, and a blinded wizard run every session from My sessions", async () => {
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.getByRole("link", { name: /Storytelling and memory/ }).click();

    await researcher.getByLabel("Hide each session's condition from wizards").check();
    await researcher.getByRole("button", { name: "Save changes" }).click();
    await researcher.getByText("Saved.").waitFor();
    await screenshot(researcher, "study-blinding");

    await researcher.getByRole("tab", { name: "Conditions" }).click();
    await researcher.getByLabel("Assignment strategy").selectOption("balanced");
    await researcher.getByRole("button", { name: "Use this strategy" }).click();
    await researcher.getByText(/Seed for the audit/).waitFor();
    for (const [i, name] of CONDITIONS.entries()) {
      await researcher.getByLabel("Condition name").fill(name);
      await researcher.getByLabel("Runs experiment").selectOption({
        label: i === 0 ? "Interactive Storyteller (nao6-ros2)" : "Storyteller, voice only (nao6-ros2)",
      });
      await researcher.getByRole("button", { name: "Add condition" }).click();
      await researcher.getByRole("cell", { name, exact: true }).waitFor();
    }

    await researcher.getByRole("tab", { name: "Participants" }).click();
    for (const code of CODES) {
      await researcher.getByLabel("Participant code").fill(code);
      await researcher.getByLabel("Consent", { exact: true }).selectOption("given");
      await researcher.getByRole("button", { name: "Add participant" }).click();
      await researcher.getByRole("button", { name: `Assign ${code}` }).click();
    }
    // Balanced: two participants in each condition.
    await expect
      .poll(async () =>
        (
          await researcher.getByRole("cell", { name: new RegExp(`^(${CONDITIONS.join("|")})$`) }).allTextContents()
        ).sort(),
      )
      .toEqual([CONDITIONS[1], CONDITIONS[1], CONDITIONS[0], CONDITIONS[0]]);

    await researcher.getByRole("tab", { name: "Sessions" }).click();
    for (const code of CODES) {
      await researcher.getByRole("combobox", { name: /^Participant/ }).selectOption({ label: code });
      await researcher.getByRole("button", { name: "Plan session" }).click();
      await researcher.getByRole("cell", { name: code, exact: true }).waitFor();
    }
    await screenshot(researcher, "study-sessions");
    await researcher.context().close();

    const wizard = await (await newContext(browser, app.url)).newPage();
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.getByRole("link", { name: "My sessions" }).click();
    const list = wizard.getByRole("list", { name: "My sessions" });
    await expect.poll(() => list.getByRole("listitem").count()).toBe(4);
    await screenshot(wizard, "my-sessions");
    const seen: string[] = [];
    for (const code of CODES) {
      seen.push(await wizard.content());
      await wizard.getByRole("button", { name: `Start the session of ${code}` }).click({ timeout: 30_000 });
      await wizard.waitForURL(/\/trials\//);
      await wizard.getByText("live", { exact: true }).waitFor();
      seen.push(await wizard.content());
      await runToTheEnd(wizard);
      seen.push(await wizard.content());
      await wizard.getByRole("link", { name: "My sessions" }).click();
      await wizard.waitForURL(/\/sessions$/);
    }
    // Every session is finished: the page, loaded afresh, has none left. Each look waits for the list to
    // load (a count taken at once, on a loaded machine, saw the page before its data and reloaded again).
    const emptyAfterReload = async () => {
      await wizard.reload();
      const empty = wizard.getByText("No sessions are planned for you.");
      return empty.waitFor({ timeout: 10_000 }).then(
        () => 1,
        () => 0,
      );
    };
    await expect.poll(emptyAfterReload, { timeout: 60_000 }).toBe(1);
    const everything = seen.join("\n");
    expect(
      [...CONDITIONS, "Interactive Storyteller", "voice only"].filter((name) => everything.includes(name)),
    ).toEqual([]);
    await wizard.context().close();

    // The study level: four finished trials, their fidelity, each step's timing.
    const results = await (await newContext(browser, app.url)).newPage();
    await signInAs(results, "researcher@demo.hristudio", DEMO_PASSWORD);
    await results.getByRole("link", { name: /Storytelling and memory/ }).click();
    await results.getByRole("tab", { name: "Results" }).click();
    await results.getByText("4 completed / 4").waitFor();
    const trialsTable = results.getByRole("region", { name: "Trials" });
    for (const code of CODES) await trialsTable.getByRole("link", { name: code }).waitFor();
    await expect
      .poll(
        async () =>
          (await trialsTable.getByRole("cell", { name: new RegExp(`^(${CONDITIONS.join("|")})$`) }).allTextContents())
            .length,
      )
      .toBe(4);
    await results
      .getByRole("img", { name: /Median time in each step/ })
      .getByText("Introduction")
      .waitFor();
    await screenshot(results, "study-results");

    // The two conditions compared: two trials each, every measure plotted and tabled, and the tidy CSV.
    const byCondition = results.getByRole("region", { name: "By condition" });
    for (const name of CONDITIONS) await byCondition.getByText(`${name}: 2 trials`, { exact: false }).waitFor();
    const fidelityPlot = byCondition.getByRole("img", { name: /^Execution fidelity: mean per condition/ });
    for (const name of CONDITIONS) await fidelityPlot.getByText(name).waitFor();
    for (const name of CONDITIONS)
      expect(await byCondition.getByRole("row", { name: new RegExp(`^${name} 2 `) }).count()).toBeGreaterThan(3);
    const csv = await results.evaluate(
      async (href) => (await fetch(href)).text(),
      results.url().replace(/\/studies\/([^/?#]+).*/, "/api/studies/$1/results-by-condition"),
    );
    expect(csv.split("\r\n")[0]).toBe("condition,measure,n,mean,sd,median,min,max");
    for (const name of CONDITIONS) expect(csv).toContain(`${name},Execution fidelity (%),2,`);
    await byCondition.getByRole("heading", { name: "By condition" }).scrollIntoViewIfNeeded();
    await screenshot(results, "study-results-by-condition");

    // The study's methods text, written from what just ran: both conditions, two participants each.
    await results.getByRole("tab", { name: "Methods" }).click();
    const methods = results.getByRole("region", { name: "Methods text" });
    await methods.getByText("between-subjects design", { exact: false }).waitFor();
    for (const name of CONDITIONS)
      await methods.getByText(`“${name}”: 2 enrolled, 2 completed, 0 withdrew; none excluded.`).waitFor();
    await methods.getByText("Wizards were blind to condition", { exact: false }).waitFor();
    await results.getByRole("button", { name: "Copy Markdown" }).waitFor();
    await screenshot(results, "study-methods");
    await results.context().close();
  }, 300_000);

  it("lets a researcher give a new trial to a wizard of the study, or to whichever wizard starts it first", async () => {
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.getByRole("link", { name: /Storytelling and memory/ }).click();
    await researcher.getByRole("tab", { name: "Trials" }).click();
    // Unassigned by default: whoever starts it is recorded as its wizard.
    expect(await researcher.getByLabel("Wizard", { exact: true }).inputValue()).toBe("any");
    for (const [code, wizard] of [
      ["P001", "Wim Wizard (wizard)"],
      ["P002", "Any wizard (the first to start it)"],
    ]) {
      await researcher
        .getByRole("combobox", { name: /^Experiment/ })
        .selectOption({ label: "Interactive Storyteller" });
      await researcher.getByText(/Runs published version/).waitFor();
      await researcher.getByRole("combobox", { name: /^Participant/ }).selectOption({ label: code });
      await researcher.getByLabel("Wizard", { exact: true }).selectOption({ label: wizard });
      await researcher.getByRole("button", { name: "Create trial" }).click();
      await researcher.getByRole("row").filter({ hasText: code }).waitFor();
    }
    await researcher
      .getByRole("row")
      .filter({ hasText: "P001" })
      .getByRole("cell", { name: "Wim Wizard", exact: true })
      .waitFor();
    await researcher
      .getByRole("row")
      .filter({ hasText: "P002" })
      .getByRole("cell", { name: "any wizard", exact: true })
      .waitFor();
    await researcher.context().close();
  }, 120_000);
  it("lets a researcher start a new study from this one, without its data, and copy an experiment back", async () => {
    const researcher = await (await newContext(browser, app.url)).newPage();
    await signInAs(researcher, "researcher@demo.hristudio", DEMO_PASSWORD);
    await researcher.getByRole("button", { name: "New study from…" }).click();
    await researcher.getByLabel("Start from").selectOption({ label: "Storytelling and memory (demo)" });
    await researcher.getByLabel("Title").fill("Storytelling, replication");
    await screenshot(researcher, "study-from-template");
    await researcher.getByRole("button", { name: "Create study" }).click();
    await researcher.waitForURL(/\/studies\/[^/?#]+$/);
    await researcher.getByRole("heading", { name: "Storytelling, replication", level: 1 }).waitFor();
    const replicationId = researcher.url().replace(/.*\/studies\/([^/?#]+).*/, "$1");

    // The design came along as drafts; the four participants and their trials did not.
    const api = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const copied = await api.experiments.list.query({ studyId: replicationId });
    expect(copied.map((e) => [e.name, e.latestVersion])).toEqual([
      ["Interactive Storyteller", null],
      ["Storyteller, voice only", null],
    ]);
    expect((await api.conditions.list.query({ studyId: replicationId })).map((c) => c.name).sort()).toEqual(
      [...CONDITIONS].sort(),
    );
    expect(await api.participants.list.query({ studyId: replicationId })).toEqual([]);
    expect(await api.trials.list.query({ studyId: replicationId })).toEqual([]);

    // An experiment of the new study, copied back into the demo study.
    await researcher.getByRole("tab", { name: "Experiments" }).click();
    await researcher.getByRole("button", { name: "Duplicate Storyteller, voice only" }).click();
    await researcher.getByLabel("Copy into").selectOption({ label: "Storytelling and memory (demo)" });
    await screenshot(researcher, "experiment-duplicate-into");
    await researcher.getByRole("button", { name: "Duplicate", exact: true }).click();
    await researcher.waitForURL(/\/experiments\//);
    const [demo] = (await api.studies.mine.query()).filter((st) => st.title === "Storytelling and memory (demo)");
    const names = (await api.experiments.list.query({ studyId: demo!.id })).map((e) => e.name);
    expect(names.filter((n) => n === "Storyteller, voice only")).toHaveLength(2);
    await researcher.context().close();
  }, 120_000);
});
