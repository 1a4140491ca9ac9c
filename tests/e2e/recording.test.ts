// Recording in a real Chromium (its fake camera and microphone feed
// MediaRecorder): parts reach the server while the trial runs (and wait, then
// go, while the upload is cut off), the trial's end saves the recording, it plays with a real duration on the analysis page
// where the timeline seeks it. A tab closed mid-recording loses nothing sent:
// the server finishes the recording from its parts, the reopened page says so
// and records again, and the analysis page plays both parts with the gap marked.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { expectAccessible } from "../support/accessibility";
import { runWholeTrial } from "../support/run-trial";
import { connectTrial } from "../support/socket";

describe.sequential("recording a trial", () => {
  let app: RunningApp;
  let browser: Browser;
  let researcher: ReturnType<typeof apiClient>;
  let wizardApi: ReturnType<typeof apiClient>;
  let versionId = "";
  let participantId = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    versionId = (await researcher.versions.publish.mutate({ experimentId: experiment!.id })).id;
    participantId = (await researcher.participants.list.query({ studyId: study!.id }))[0]!.id;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  const wizardPage = async (trialId: string) => {
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "wizard@demo.hristudio", DEMO_PASSWORD);
    await page.goto(`/trials/${trialId}`);
    await page.getByText("live", { exact: true }).waitFor();
    return page;
  };
  const partsSaved = async (page: Awaited<ReturnType<typeof wizardPage>>, atLeast: number) =>
    expect
      .poll(
        async () =>
          Number(/^(\d+) part/.exec((await page.getByTestId("recording-parts").textContent()) ?? "")?.[1] ?? 0),
        { timeout: 30_000 },
      )
      .toBeGreaterThanOrEqual(atLeast);

  it("records while the trial runs, saves at its end, and plays in step with the timeline", async () => {
    const trial = await wizardApi.trials.create.mutate({ versionId, participantId });
    const wizard = await wizardPage(trial.id);
    await wizard.getByRole("button", { name: "Start recording" }).click();
    await wizard.getByTestId("recording-indicator").waitFor();
    await partsSaved(wizard, 1);
    await screenshot(wizard, "wizard-recording");
    // The upload is cut off for a while: parts wait in the browser, then go when it is back.
    const chunks = "**/api/recordings/*/chunks/*";
    await wizard.route(chunks, (route) => route.abort("internetdisconnected"));
    await wizard.getByText(/waiting to be sent/).waitFor({ timeout: 15_000 });
    await wizard.getByText(/the recording continues and its parts are sent when it is back/).waitFor();
    await wizard.unroute(chunks);
    await expect
      .poll(async () => (await wizard.getByTestId("recording-parts").textContent()) ?? "", { timeout: 30_000 })
      .not.toMatch(/waiting/);
    await runWholeTrial(wizardApi, trial.id);
    await wizard.getByText("The recording is saved with this trial.").waitFor({ timeout: 30_000 });
    const [recording] = await researcher.recordings.list.query({ trialId: trial.id });
    expect(recording).toMatchObject({
      status: "complete",
      kind: "video",
      mimeType: expect.stringMatching(/^video\/webm/),
    });
    expect(recording!.offsetMs).toEqual(expect.any(Number));
    expect(recording!.durationMs).toBeGreaterThan(2000);
    // The measured offset is in the trial's own log, as an event.
    const log = await researcher.trials.events.query({ trialId: trial.id });
    expect(log.find((e) => e.type === "recording.started")).toMatchObject({
      recordingId: recording!.id,
      offsetMs: recording!.offsetMs,
    });

    const analysis = await (await newContext(browser, app.url)).newPage();
    await signInAs(analysis, "researcher@demo.hristudio", DEMO_PASSWORD);
    await analysis.goto(`/trials/${trial.id}/analysis`);
    const video = analysis.getByTestId("trial-video");
    // Chrome's own recordings declare no duration; the server wrote it in, so the player knows it and can seek.
    await expect
      .poll(() => video.evaluate((v: HTMLVideoElement) => v.duration), { timeout: 15_000 })
      .toBeCloseTo(recording!.durationMs! / 1000, 0);
    const row = analysis.getByRole("button", { name: /trial\.completed/ });
    await row.click();
    await expect.poll(() => video.evaluate((v: HTMLVideoElement) => v.currentTime)).toBeGreaterThan(0.5);
    await expect.poll(() => row.getAttribute("aria-current")).toBe("time");
    // The chart: an action bar seeks the video too, and the playhead follows.
    await analysis.getByLabel("Timeline chart").scrollIntoViewIfNeeded();
    await analysis
      .getByRole("button", { name: /^Action .* at / })
      .first()
      .click({ force: true });
    // The first action came right after t0: in the recording, that is its offset from t0 in.
    await expect
      .poll(() => video.evaluate((v: HTMLVideoElement) => v.currentTime))
      .toBeCloseTo(-recording!.offsetMs! / 1000, 0);
    await analysis.getByTestId("playhead").waitFor();
    // The robot's joint angles share the clock: a click on their chart seeks the video there, and their
    // playhead stands where it was clicked. Two clicks a fifth of the chart apart move the video by a
    // fifth of the chart's span (its label gives the span in whole seconds: within a second).
    const joints = analysis.getByRole("img", { name: /^Joint angles of / });
    await joints.scrollIntoViewIfNeeded();
    const span = Number(/over (\d+) s$/.exec((await joints.getAttribute("aria-label")) ?? "")?.[1]);
    const box = (await joints.boundingBox())!;
    const seekAt = async (fraction: number) => {
      const before = await video.evaluate((v: HTMLVideoElement) => v.currentTime);
      await joints.click({ position: { x: box.width * fraction, y: box.height / 2 } });
      await expect.poll(() => video.evaluate((v: HTMLVideoElement) => v.currentTime)).not.toBe(before);
      await expect
        .poll(async () => Number(await analysis.getByTestId("samples-playhead").getAttribute("x1")))
        .toBeCloseTo(1000 * fraction, -1);
      return video.evaluate((v: HTMLVideoElement) => v.currentTime);
    };
    const early = await seekAt(0.2);
    const later = await seekAt(0.4);
    expect(Math.abs(later - early - span / 5)).toBeLessThan(1);
    // An annotation made afterwards, at the playhead, then edited.
    const marked = analysis.getByRole("region", { name: "Annotations" });
    await marked.getByLabel("What happened").fill("Participant leans in");
    await marked.getByRole("button", { name: /^Annotate at / }).click();
    await marked.getByRole("button", { name: "Edit “Participant leans in”" }).click();
    await marked.getByLabel("Edit the note").fill("towards the robot");
    await marked.getByRole("button", { name: "Save" }).click();
    await marked.getByText("towards the robot").waitFor();
    await analysis.evaluate(() => window.scrollTo(0, 0));
    await screenshot(analysis, "analysis-video");
    await Promise.all([wizard.context().close(), analysis.context().close()]);
  }, 180_000);

  it("finishes a recording cut off by a closed tab from its parts, says so on the reopened page, and plays both parts", async () => {
    const trial = await wizardApi.trials.create.mutate({ versionId, participantId });
    const { url, token } = await wizardApi.trials.socketToken.mutate({ trialId: trial.id });
    const socket = await connectTrial(url, token);
    await socket.command("start", { kind: "start" });
    socket.close();
    const wizard = await wizardPage(trial.id);
    await wizard.getByRole("button", { name: "Start recording" }).click();
    await partsSaved(wizard, 2);
    await wizard.context().close(); // the tab is gone, mid-recording

    // The wizard opens the trial again: the server finishes what the closed page left, and the page says so.
    const again = await wizardPage(trial.id);
    const told = again.getByTestId("recording-cut-off");
    await told.waitFor({ timeout: 60_000 });
    expect(await told.textContent()).toMatch(
      /^The recording stopped when the page closed at \d{1,2}:\d{2}.*; the \d+ seconds before are kept\.$/,
    );
    await expectAccessible(again, "the wizard's page after a recording was cut off");
    await again.getByRole("button", { name: "Record again" }).click();
    await partsSaved(again, 1);
    await runWholeTrial(wizardApi, trial.id);
    await again.getByText("The recording is saved with this trial.").waitFor({ timeout: 30_000 });
    const recordings = await researcher.recordings.list.query({ trialId: trial.id });
    expect(recordings).toMatchObject([
      { status: "complete", cutOff: true },
      { status: "complete", cutOff: false },
    ]);
    expect(recordings[0]!.durationMs).toBeGreaterThan(2000);

    // The analysis page plays the cut-off part first, then the second; the gap between them says why.
    const analysis = await (await newContext(browser, app.url)).newPage();
    await signInAs(analysis, "researcher@demo.hristudio", DEMO_PASSWORD);
    await analysis.goto(`/trials/${trial.id}/analysis`);
    const video = analysis.getByTestId("trial-video");
    const playable = () =>
      expect
        .poll(() => video.evaluate((v: HTMLVideoElement) => (v.readyState >= 1 ? v.duration : 0)), { timeout: 15_000 })
        .toBeGreaterThan(0);
    await playable();
    expect(await video.getAttribute("src")).toBe(`/api/recordings/${recordings[0]!.id}/media`);
    await analysis.getByText("The recording is in 2 parts").waitFor();
    await analysis
      .getByTestId("recording-gap")
      .getByText(/: the wizard's page closed\.$/)
      .waitFor();
    await analysis.getByRole("button", { name: /^Not recorded from .*: the wizard's page closed$/ }).waitFor();
    await analysis.getByRole("button", { name: /^Part 2/ }).click();
    await expect.poll(() => video.getAttribute("src")).toBe(`/api/recordings/${recordings[1]!.id}/media`);
    await playable();
    await Promise.all([again.context().close(), analysis.context().close()]);
  }, 240_000);

  it("refuses parts of the wrong type or over the size limit, saying why", async () => {
    const trial = await wizardApi.trials.create.mutate({ versionId, participantId });
    const { recordingId } = await wizardApi.recordings.start.mutate({
      trialId: trial.id,
      kind: "video",
      mimeType: "video/webm",
    });
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "wizard@demo.hristudio", DEMO_PASSWORD);
    const wrongType = await page.request.put(`/api/recordings/${recordingId}/chunks/0`, {
      headers: { "content-type": "text/x-shellscript" },
      data: "echo hi",
    });
    expect([wrongType.status(), await wrongType.text()]).toEqual([
      415,
      'This recording is video/webm; a part sent as "text/x-shellscript" is refused.',
    ]);
    // Refused from its declared length, before a byte is read: the server may answer and close while
    // the client is still sending, which the client then sees as a broken pipe. Either way nothing is stored.
    const tooBig = await page.request
      .put(`/api/recordings/${recordingId}/chunks/0`, {
        headers: { "content-type": "video/webm" },
        data: Buffer.alloc(17 * 1024 * 1024),
      })
      .then(
        async (res) => [res.status(), await res.text()],
        (error: Error) =>
          /EPIPE|ECONNRESET|socket hang up/.test(error.message) ? "cut off while sending" : error.message,
      );
    expect([
      [413, "A part of a recording may be at most 16 MB; this one is 17 MB."],
      "cut off while sending",
    ]).toContainEqual(tooBig);
    const observer = await (await newContext(browser, app.url)).newPage();
    await signInAs(observer, "observer@demo.hristudio", DEMO_PASSWORD);
    const notTheirs = await observer.request.put(`/api/recordings/${recordingId}/chunks/0`, {
      headers: { "content-type": "video/webm" },
      data: Buffer.alloc(10),
    });
    expect(notTheirs.status()).toBe(403);
    await Promise.all([page.context().close(), observer.context().close()]);
  }, 60_000);
});
