// More screens that must say what is true, as a research team found them
// wrong: a posture the last trial left, carried into the next unannounced; no
// view of the wizard's own camera; the robot camera's last picture left on
// screen after the trial as if it were live; the robot's camera sent to a
// page that does not show it.
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { WebSocket } from "ws";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";
import { apiClient, signIn } from "../support/http";
import { runToTheEndInPage } from "../support/run-trial";

/** Sets the simulated robot's posture as a last trial's "sit" would, over its rosbridge socket. */
async function setPosture(url: string, posture: string) {
  const socket = new WebSocket(url);
  await new Promise((resolve, reject) => socket.once("open", resolve).once("error", reject));
  socket.send(JSON.stringify({ op: "advertise", topic: "/posture", type: "std_msgs/msg/String" }));
  socket.send(JSON.stringify({ op: "publish", topic: "/posture", msg: { data: posture } }));
  const closed = new Promise((resolve) => socket.once("close", resolve));
  socket.close();
  await closed;
}

describe.sequential("more screens that say what is true", () => {
  let app: RunningApp;
  let browser: Browser;
  let trialId = "";

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    trialId = (await wizardApi.trials.create.mutate({ versionId: version.id, participantId: participant!.id })).id;
  });
  afterAll(async () => {
    await browser?.close();
    await app?.stop();
  });

  it("tells the wizard of a carried posture, shows their own camera muted, sends the robot's camera only while shown, and marks its last picture frozen", async () => {
    await setPosture(app.simulatorUrl, "sit");
    const wizard = await (await newContext(browser, app.url)).newPage();
    // The trial socket's frames both ways, as the page sends and receives them.
    const received: string[] = [];
    const sent: string[] = [];
    wizard.on("websocket", (socket) => {
      socket.on("framereceived", ({ payload }) => void received.push(String(payload)));
      socket.on("framesent", ({ payload }) => void sent.push(String(payload)));
    });
    await signInAs(wizard, "wizard@demo.hristudio", DEMO_PASSWORD);
    await wizard.goto(`/trials/${trialId}`);
    await wizard.getByText("live", { exact: true }).waitFor();
    // Before the start: the robot sits, as the last trial left it, where the trial starts standing.
    await expect
      .poll(() => wizard.getByTestId("posture-carried").textContent(), { timeout: 30_000 })
      .toMatch(/is in the posture "sit", as the last trial or session left it; it starts in "stand"/);

    // Recording: a small self-view of the fake camera, muted, a frame decoded.
    await wizard.getByRole("button", { name: "Start recording" }).click();
    const selfView = wizard.getByTestId("self-view");
    await selfView.waitFor({ timeout: 30_000 });
    const frame = await selfView.evaluate(
      (video: HTMLVideoElement) =>
        new Promise<{ width: number; muted: boolean }>((resolve) =>
          video.requestVideoFrameCallback(() => resolve({ width: video.videoWidth, muted: video.muted })),
        ),
    );
    expect(frame.width).toBeGreaterThan(0);
    expect(frame.muted).toBe(true);

    await wizard.getByRole("button", { name: "Start trial" }).click();
    await expect.poll(() => wizard.getByTestId("trial-status").textContent(), { timeout: 30_000 }).toBe("in progress");
    await expect(wizard.getByTestId("posture-carried").count()).resolves.toBe(0);
    const robot = wizard.getByTestId("robot-camera");
    await robot.waitFor({ timeout: 30_000 });
    expect(await robot.getAttribute("alt")).toBe("The robot's camera, live");
    expect(await wizard.getByTestId("robot-camera-frozen").count()).toBe(0);

    // Hidden, with its button or with the whole tab, the page asks for no pictures and gets none.
    const cameraFrames = () => received.filter((f) => f.startsWith('{"type":"camera"')).length;
    const said = () => sent.filter((f) => f.startsWith('{"type":"camera"')).map((f) => JSON.parse(f));
    /** Once the runtime answered the page's last word on the camera: the frames received by then, and a while later (7 frames' time). */
    const framesAfterAnswer = async () => {
      const { requestId } = said().at(-1)!;
      await expect.poll(() => received.some((f) => f.includes(`"requestId":"${requestId}"`))).toBe(true);
      const at = cameraFrames();
      await wizard.waitForTimeout(1500);
      return { at, after: cameraFrames() };
    };
    await wizard.getByRole("button", { name: "Hide the robot's camera" }).click();
    await wizard.getByTestId("robot-camera-hidden").waitFor();
    expect(await robot.count()).toBe(0);
    expect(said().map((m) => m.watch)).toEqual([false]);
    const hidden = await framesAfterAnswer();
    expect(hidden.after).toBe(hidden.at);
    await wizard.getByRole("button", { name: "Show the robot's camera" }).click();
    await robot.waitFor();
    await expect.poll(cameraFrames).toBeGreaterThan(hidden.after);
    const tab = (state: "hidden" | "visible") =>
      wizard.evaluate((visibility) => {
        Object.defineProperty(document, "visibilityState", { value: visibility, configurable: true });
        document.dispatchEvent(new Event("visibilitychange"));
      }, state);
    await tab("hidden");
    expect(said().map((m) => m.watch)).toEqual([false, true, false]);
    const away = await framesAfterAnswer();
    expect(away.after).toBe(away.at);
    await tab("visible");
    await expect.poll(cameraFrames).toBeGreaterThan(away.after);
    expect(said().map((m) => m.watch)).toEqual([false, true, false, true]);

    // After the end the last picture stays, said to be frozen.
    await runToTheEndInPage(wizard);
    await wizard.getByTestId("robot-camera-frozen").waitFor();
    expect(await robot.getAttribute("alt")).toBe("The robot's camera, its last picture (frozen)");
    await screenshot(wizard, "wizard-after-trial-frozen-camera");
  });
});
