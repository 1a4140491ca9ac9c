// A researcher in the designer, in a real Chromium: every click, key, fill
// and drag they make, counted, with the gestures the designer tests share.
import type { Locator, Page } from "playwright-core";
import { expectAccessible } from "./accessibility";

export class Researcher {
  operations = 0;
  constructor(readonly page: Page) {}

  get properties() {
    return this.page.getByRole("region", { name: "Properties" });
  }
  async click(target: Locator) {
    this.operations++;
    await target.click();
  }
  async fill(target: Locator, text: string) {
    this.operations++;
    await target.fill(text);
  }
  async selectOption(target: Locator, label: string) {
    this.operations++;
    await target.selectOption({ label });
  }
  async check(target: Locator) {
    this.operations++;
    await target.check();
  }
  /** Drags a library block into a step's drop zone, the way a mouse does. */
  async drag(blockType: string, stepName: string) {
    this.operations++;
    const source = this.page.locator(`[data-block="${blockType}"]`);
    const target = this.page.locator(`[data-drop-zone="${stepName}"]`);
    // Centred, so the pointer is nowhere near an edge that would scroll the list while dragging.
    await source.evaluate((el) => el.scrollIntoView({ block: "center" }));
    await target.evaluate((el) => el.scrollIntoView({ block: "center" }));
    const s = (await source.boundingBox())!;
    const t = (await target.boundingBox())!;
    await this.page.mouse.move(s.x + s.width / 2, s.y + s.height / 2);
    await this.page.mouse.down();
    await this.page.mouse.move(s.x + s.width / 2 + 12, s.y + s.height / 2, { steps: 3 });
    await this.page.mouse.move(t.x + t.width / 2, t.y + t.height / 2, { steps: 12 });
    // The timeline may have moved under the pointer as the drag began (an open block's properties, a slow
    // render): the drop lands where the zone is now, not where it was.
    const now = (await target.boundingBox())!;
    await this.page.mouse.move(now.x + now.width / 2, now.y + now.height / 2, { steps: 2 });
    await this.page.mouse.up();
    // A new block is selected: its properties open beside the timeline. ("Run together" adds none.)
    const name = (await source.locator("span").first().textContent())!;
    if (blockType !== "run_together") await this.properties.getByRole("heading", { name, exact: true }).waitFor();
    // dnd-kit swallows a click in the 50 ms after a drop (the click a drop can cause);
    // nobody clicks that fast, but a test would.
    await this.page.waitForTimeout(100);
  }
  async addStep(name: string) {
    await this.click(this.page.getByRole("button", { name: "Add step" }));
    await this.fill(this.properties.getByLabel("Step name"), name);
  }
  async say(stepName: string, text: string) {
    await this.drag("say", stepName);
    await this.fill(this.properties.getByLabel("Text"), text);
  }
  async gestureWithSpeech(stepName: string, type: string) {
    await this.drag(type, stepName);
    await this.check(this.properties.getByLabel("Starts together with the action above"));
  }
  /** From the study list to an empty designer: the demo study's Experiments tab, New experiment, Create. */
  async createExperiment(name: string) {
    const page = this.page;
    await this.click(page.getByRole("link", { name: /Storytelling and memory/ }).first());
    await this.click(page.getByRole("tab", { name: "Experiments" }));
    await this.click(page.getByRole("button", { name: "New experiment" }));
    await this.fill(page.getByLabel("Name"), name);
    await expectAccessible(page, "the New experiment dialog");
    const traffic: string[] = [];
    page.on("request", (req) => void traffic.push(`sent ${req.method()} ${req.url().slice(0, 120)}`));
    page.on(
      "response",
      (res) => void traffic.push(`${res.status()} ${res.request().method()} ${res.url().slice(0, 120)}`),
    );
    page.on(
      "requestfailed",
      (req) => void traffic.push(`failed ${req.method()} ${req.url().slice(0, 120)} ${req.failure()?.errorText}`),
    );
    page.on("console", (m) => void traffic.push(`console ${m.type()} ${m.text().slice(0, 200)}`));
    await this.click(page.getByRole("button", { name: "Create experiment" }));
    // Creating opens the designer. On a loaded machine the switch can lag: the new
    // experiment's Design link in the list is the same way in.
    const opened = await page.waitForURL(/\/experiments\//, { timeout: 20_000 }).then(
      () => true,
      () => false,
    );
    if (!opened) {
      await page
        .getByRole("link", { name: `Design ${name}` })
        .click({ timeout: 60_000 })
        .catch(async (error: unknown) => {
          const shown = (await page.locator("body").innerText()).slice(0, 2000);
          throw new Error(
            `Creating the experiment opened nothing. The page shows:\n${shown}\nTRAFFIC\n${traffic.join("\n")}`,
            { cause: error },
          );
        });
      await page.waitForURL(/\/experiments\//, { timeout: 60_000 });
    }
  }
}
