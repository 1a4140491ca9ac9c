// Observing a live trial in a real Chromium: the wizard records (the fake
// camera and microphone) and runs the trial; two observers, each in a context
// of their own, find it under "Live now" and, one click later, see the
// wizard's camera over WebRTC (a frame decoded in each page) with the
// connection's quality in words, and the simulated robot's own camera.
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { explained } from "../support/explain";
import { apiClient, signIn } from "../support/http";

const SECOND_OBSERVER = { email: "second-observer@demo.hristudio", password: "second-observer-pw" };

describe.sequential("observing a live trial", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const admin = apiClient(app.url, await signIn(app.url, "admin@demo.hristudio", DEMO_PASSWORD));
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    await admin.admin.users.create.mutate({ name: "Oda Observer", role: "observer", ...SECOND_OBSERVER });
    await researcher.members.add.mutate({ studyId: study!.id, email: SECOND_OBSERVER.email, role: "observer" });
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    trialId = (await wizardApi.trials.create.mutate({ versionId: version.id, participantId: participant!.id })).id;
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
    const wizard = await personPage("wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("live", { exact: true }).waitFor();
    await wizard.getByRole("button", { name: "Start recording" }).click();
    await wizard.getByTestId("recording-indicator").waitFor();
    await wizard.getByRole("button", { name: "Start trial" }).click();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent(), { timeout: 30_000 }).toBe("in progress");

    // Each observer: the dashboard's "Live now", one click to watch.
    const observers: Page[] = [];
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
    for (const page of [...observers, wizard]) await page.context().close();
  }, 240_000);
});
