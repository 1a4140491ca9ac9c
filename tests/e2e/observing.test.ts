// Observing a live trial in a real Chromium: the wizard records (the fake
// camera and microphone) and runs the trial; two observers, each in a context
// of their own, find it under "Live now" and, one click later, see the
// wizard's camera over WebRTC (a frame decoded in each page) with the
// connection's quality in words, and the simulated robot's own camera. Then
// both code what they see with the study's published scheme, one key per code,
// each into a tier of their own; once the wizard has ended the trial, its
// analysis page shows both tiers and the observers' Cohen's kappa per set.
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { explained } from "../support/explain";
import { agreement, type CodeMark } from "../../src/core/coding/agreement";
import type { Scheme } from "../../src/core/coding/scheme";
import { apiClient, signIn } from "../support/http";

const SECOND_OBSERVER = { email: "second-observer@demo.hristudio", password: "second-observer-pw" };

describe.sequential("observing a live trial", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";
  let researcher: ReturnType<typeof apiClient>;
  // The live pages, kept from watching to coding: the same trial, still running.
  let wizard: Page;
  const observers: Page[] = [];

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const admin = apiClient(app.url, await signIn(app.url, "admin@demo.hristudio", DEMO_PASSWORD));
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    await admin.admin.users.create.mutate({ name: "Oda Observer", role: "observer", ...SECOND_OBSERVER });
    await researcher.members.add.mutate({ studyId: study!.id, email: SECOND_OBSERVER.email, role: "observer" });
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    // Published at seed: a newcomer's first trial needs no "Publish" first.
    const [version] = await researcher.versions.list.query({ experimentId: experiment!.id });
    expect(version!.version).toBe(1);
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    trialId = (await wizardApi.trials.create.mutate({ versionId: version!.id, participantId: participant!.id })).id;
    // The scheme the observers code with: Gaze (states, one set) and Expression (point events, another).
    const scheme = await researcher.coding.createScheme.mutate({
      studyId: study!.id,
      template: "participant-engagement",
    });
    await researcher.coding.publishScheme.mutate({ codingSchemeId: scheme.id });
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  const personPage = async (email: string, password: string) => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, email, password);
    return page;
  };

  /** A frame of the live video decoded in this page: a size, and the browser's own per-frame callback. */
  const videoFrameDecoded = (page: Page) =>
    page.evaluate(
      () =>
        new Promise<{ width: number; height: number }>((resolve) => {
          const video = document.querySelector<HTMLVideoElement>("[data-testid=live-video]")!;
          video.requestVideoFrameCallback(() => resolve({ width: video.videoWidth, height: video.videoHeight }));
        }),
    );

  it("shows two observers the wizard's camera and the robot's, live, while the wizard records and runs", async () => {
    wizard = await personPage("wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("live", { exact: true }).waitFor();
    await wizard.getByRole("button", { name: "Start recording" }).click();
    await wizard.getByTestId("recording-indicator").waitFor();
    await wizard.getByRole("button", { name: "Start trial" }).click();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent(), { timeout: 30_000 }).toBe("in progress");

    // Each observer: the dashboard's "Live now", one click to watch.
    for (const [email, password] of [
      ["observer@demo.hristudio", DEMO_PASSWORD],
      [SECOND_OBSERVER.email, SECOND_OBSERVER.password],
    ] as const) {
      const page = await personPage(email, password);
      await page.goto("/studies");
      const live = page.getByRole("region", { name: "Live now" });
      await live.getByRole("link", { name: "Watch" }).click();
      await page.waitForURL(`**/trials/${trialId}`);
      observers.push(page);
    }
    await expect
      .poll(() => wizard.getByTestId("video-sending").textContent(), { timeout: 30_000 })
      .toMatch(/go to 2 watching/);

    for (const page of observers) {
      await explained(page.getByTestId("live-video").waitFor({ state: "visible", timeout: 30_000 }), {
        app,
        trialIds: [trialId],
        pages: [wizard, page],
      });
      const frame = await videoFrameDecoded(page);
      expect(frame.width).toBeGreaterThan(0);
      expect(frame.height).toBeGreaterThan(0);
      // The connection's quality, in words, from WebRTC's own statistics.
      await expect
        .poll(() => page.getByTestId("video-quality").textContent(), { timeout: 30_000 })
        .toMatch(/picture \(.*packets lost, \d+ ms there and back\)/);
      // The simulated robot's camera: a JPEG decoded in the page.
      const robot = page.getByTestId("robot-camera");
      await robot.waitFor({ timeout: 30_000 });
      await expect
        .poll(() => robot.evaluate((img: HTMLImageElement) => img.complete && img.naturalWidth), { timeout: 10_000 })
        .toBeGreaterThan(0);
    }
    // The wizard sees what the robot sees too, and the recording goes on, parts reaching the server.
    await wizard.getByTestId("robot-camera").waitFor();
    await expect
      .poll(
        async () =>
          Number(/^(\d+) part/.exec((await wizard.getByTestId("recording-parts").textContent()) ?? "")?.[1] ?? 0),
        { timeout: 30_000 },
      )
      .toBeGreaterThanOrEqual(1);
    await screenshot(observers[0]!, "observer-live-video");
    await observers[0]!.goto("/studies");
    await screenshot(observers[0]!, "live-now");
    await observers[0]!.goto(`/trials/${trialId}`);
  }, 240_000);

  it("lets the two observers code with keys, and the analysis shows both tiers and their kappa", async () => {
    expect(observers, "the observers of the test before watch the trial").toHaveLength(2);
    const [olu, oda] = observers as [Page, Page];
    const marked = (page: Page) => page.getByText(/^\d+ codes? marked/);
    /** One key press, confirmed by the runtime: the page counts it and names it as my last code. */
    const press = async (page: Page, key: string, count: number, name: string) => {
      await page.keyboard.press(key);
      // The runtime's confirmation may take longer than expect.poll's default second in a loaded run.
      await expect
        .poll(() => marked(page).textContent(), { timeout: 15_000 })
        .toBe(`${count} code${count === 1 ? "" : "s"} marked; last: ${name}`);
    };
    for (const page of observers) await marked(page).waitFor({ timeout: 30_000 });
    // The panel shows before the page's connection is welcomed (the last test reloaded one page): a key
    // pressed before it is open is refused, and says so; it is pressed once the page is live, as an observer would.
    for (const page of observers)
      await expect.poll(() => page.getByTestId("runtime-status").textContent(), { timeout: 30_000 }).toBe("live");
    // Both look at the robot; then Olu sees a smile and the gaze move to the task,
    // Oda a hesitation and the gaze move away: they agree on some slices, not all.
    // Each page counts its own codes alone: nobody else's are shown while coding.
    await press(olu, "r", 1, "At the robot");
    await press(oda, "r", 1, "At the robot");
    await press(olu, "s", 2, "Smile");
    await press(oda, "e", 2, "Hesitation");
    // "At the task" ends "At the robot" (one set, its codes exclude one another): a third code, the state held lit.
    await press(olu, "k", 3, "At the task");
    await press(oda, "a", 3, "Away");
    await olu.locator("li[data-held]").filter({ hasText: "At the task" }).waitFor();
    expect(await olu.locator("li[data-held]").count()).toBe(1);
    await olu
      .getByRole("heading", { name: "Coding", exact: true })
      .evaluate((h) => h.scrollIntoView({ block: "start" }));
    await screenshot(olu, "observer-coding");

    await wizard.getByRole("button", { name: "Complete trial" }).click();
    for (const page of observers)
      await expect.poll(() => page.getByTestId("trial-status").textContent(), { timeout: 30_000 }).toBe("completed");
    // Ended, the observer's page codes afterwards: their own tier alone, to add to, move and delete.
    const mine = olu.getByRole("region", { name: "Code this trial afterwards" });
    await expect
      .poll(() => mine.getByRole("region", { name: "Tier My codes - Gaze" }).getByRole("listitem").allTextContents())
      .toHaveLength(2);
    expect(await mine.getByRole("region", { name: /^Tier / }).count()).toBe(2);
    await mine.getByRole("button", { name: "Add a code" }).waitFor();
    for (const page of [...observers, wizard]) await page.context().close();

    // The kappa the page must show, derived here with the project's own pure function from what was
    // stored: the codes as the runtime timed them, and the trial from its start to its end, in 1 s slices.
    const [codes, trial, definition] = await Promise.all([
      researcher.coding.codes.query({ trialId }),
      researcher.trials.get.query({ trialId }),
      researcher.coding.forTrial.query({ trialId }).then((f) => f.schemes[0]!.definition as Scheme),
    ]);
    const tierOf = (name: string) => codes.filter((c) => c.observerName === name) as CodeMark[];
    const expected = agreement(
      definition.sets,
      [
        {
          durationMs: new Date(trial.endedAt!).getTime() - new Date(trial.t0!).getTime(),
          a: tierOf("Olu Observer"),
          b: tierOf("Oda Observer"),
        },
      ],
      1000,
    );
    // Expression: Olu's only code is a smile, Oda's a hesitation, so some slice disagrees (kappa < 1)
    // and the slices hold more than one category (kappa defined): the figure says something.
    const expression = expected.find((s) => s.setId === "expression")!;
    expect(expression.kappa).not.toBeNull();
    expect(expression.kappa).toBeLessThan(1);

    const page = await personPage("researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/trials/${trialId}/analysis`);
    const tier = (name: string) => page.getByRole("region", { name: `Tier ${name}` }).getByRole("listitem");
    await expect.poll(() => tier("Olu Observer - Gaze").allTextContents(), { timeout: 30_000 }).toHaveLength(2);
    for (const [name, names] of [
      // The states each observer's last key began were never ended: they hold to the trial's end.
      ["Olu Observer - Gaze", ["At the robot", "At the task"]],
      ["Olu Observer - Expression", ["Smile"]],
      ["Oda Observer - Gaze", ["At the robot", "Away"]],
      ["Oda Observer - Expression", ["Hesitation"]],
    ] as const) {
      const texts = await tier(name).allTextContents();
      expect(texts, name).toHaveLength(names.length);
      names.forEach((code, i) => expect(texts[i], name).toContain(code));
      if (name.endsWith("Gaze")) {
        expect(texts[0], name).toMatch(/\d s – \d+\.\d s/);
        expect(texts[1], name).toContain("held to the end");
      }
    }
    const panel = page.getByRole("region", { name: "Agreement between observers" });
    await panel
      .getByText(/^(Olu|Oda) Observer \(rows\) and (Olu|Oda) Observer \(columns\), in this trial\.$/)
      .waitFor();
    for (const set of expected)
      expect(await panel.locator(`[data-kappa="${set.setId}"]`).textContent(), set.setId).toBe(
        set.kappa === null ? "undefined" : set.kappa.toFixed(2),
      );
    // In the scheme's words: the set's name over its kappa, the codes' names heading its confusion table.
    await panel.getByRole("heading", { name: /^Gaze: Cohen's κ = / }).waitFor();
    expect(
      await panel.getByRole("table", { name: "Confusion table of Gaze" }).getByRole("columnheader").allTextContents(),
    ).toEqual(["", "At the robot", "At the task", "Away", "(none)"]);
    await page
      .getByRole("heading", { name: "Codes", exact: true })
      .evaluate((h) => h.scrollIntoView({ block: "start" }));
    await screenshot(page, "analysis-coding");

    // On the study's Results tab the researcher counts from when both had coded, keeps it, and the methods text says so.
    await page.getByRole("link", { name: "← Study" }).click();
    await page.getByRole("tab", { name: "Results" }).click();
    const study = page.getByRole("region", { name: "Agreement between observers" });
    await study.getByText("The methods text counts agreement as shown here.").waitFor();
    await study.getByLabel("Counted").selectOption("bothCoding");
    await study.getByText("The methods text counts 1 s slices, the whole trial.").waitFor();
    await study.getByRole("button", { name: "Keep this count for the methods text" }).click();
    await study.getByText("The methods text counts agreement as shown here.").waitFor();
    await page.getByRole("tab", { name: "Methods" }).click();
    await page
      .getByRole("region", { name: "Methods text" })
      .getByText("agreement was counted in 1 s slices, from when both observers had coded", { exact: false })
      .waitFor();
    await page.context().close();
  }, 240_000);
});
