// The simulated robot's Robot page makes it sense, in a real Chromium: a
// touch on its head, a phrase it hears with a confidence, someone stepping
// close. A roslib client beside it, as a trial's robot link would, gets each
// on the event's own topic as the real message type.
import * as ROSLIB from "roslib";
import type { Browser } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { launchBrowser, newContext, screenshot, signInAs } from "../support/browser";

describe.sequential("the simulated robot's senses on its Robot page", () => {
  let app: RunningApp;
  let browser: Browser;
  let ros: ROSLIB.Ros;

  beforeAll(async () => {
    app = await startApp();
    browser = await launchBrowser();
    ros = new ROSLIB.Ros({ url: app.simulatorUrl });
    await new Promise<void>((ok, fail) => {
      ros.on("connection", () => ok());
      ros.on("error", (e) => fail(new Error(`Could not reach the simulated robot: ${String(e)}`)));
    });
  }, 180_000);
  afterAll(async () => {
    ros?.close();
    await browser?.close();
    await app?.stop();
  });

  const heard = (name: string, messageType: string) => {
    const messages: Array<Record<string, unknown>> = [];
    new ROSLIB.Topic({ ros, name, messageType }).subscribe((m) => messages.push(m as Record<string, unknown>));
    return messages;
  };

  it("a head touch, a phrase and a step close reach the robot's topics as its sensors would send them", async () => {
    const head = heard("/head_touch", "naoqi_bridge_msgs/msg/HeadTouch");
    const words = heard("/word_recognized", "naoqi_bridge_msgs/msg/WordRecognized");
    const sonar = heard("/sonar/left", "sensor_msgs/msg/Range");
    const page = await (await newContext(browser, app.url)).newPage();
    await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
    await page.goto("/robot");
    const senses = page.getByRole("region", { name: "What the robot senses" });

    await senses.getByRole("button", { name: "Head touched", exact: true }).click();
    await expect
      .poll(() => head, { timeout: 10_000 })
      .toEqual([
        { button: 2, state: 1 },
        { button: 2, state: 0 },
      ]);

    await senses.getByLabel("A phrase the robot hears").fill("ready");
    await senses.getByLabel("Confidence (0–1)").fill("0.9");
    await senses.getByRole("button", { name: "Hear it" }).click();
    await expect.poll(() => words, { timeout: 10_000 }).toEqual([{ words: ["ready"], confidence_values: [0.9] }]);

    await senses.getByRole("button", { name: "Step close (Someone close on the left)" }).click();
    await expect.poll(() => (sonar.at(-1)?.range as number) ?? 9, { timeout: 10_000 }).toBeLessThan(0.5);
    await senses.getByRole("button", { name: "Step away (Someone close on the left)" }).waitFor();
    await senses
      .getByRole("status", { name: "Last sensed" })
      .getByText(/Stepped close/)
      .waitFor();
    await screenshot(page, "robot-senses");
    await page.context().close();
  });
});
