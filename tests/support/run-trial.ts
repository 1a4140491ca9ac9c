// Runs a whole trial as a wizard would: start, then "next" until the end,
// choosing the first answer when asked (or the answer-th); over the runtime
// socket, for tests that need a finished trial rather than to test running
// one, or in the wizard's page with its keys.
import type { Page } from "playwright-core";
import { expect } from "vitest";
import type { apiClient } from "./http";
import { connectTrial } from "./socket";

export async function runWholeTrial(
  wizard: ReturnType<typeof apiClient>,
  trialId: string,
  /** A wizard's pause after each press, for a trial that must take a while (a replay to watch); the answer to give, by index. */
  { pauseMs = 0, answer = 0 } = {},
) {
  const trial = await wizard.trials.get.query({ trialId });
  const { url, token } = await wizard.trials.socketToken.mutate({ trialId });
  const socket = await connectTrial(url, token);
  const question = trial.protocol.steps.flatMap((s) => s.actions).find((a) => a.type === "record_answer")!;
  const options = question.parameters.options as Array<{ id: string }>;
  await socket.command("start", { kind: "start" });
  let completed = false;
  for (let i = 0; i < 200 && !completed; i++) {
    const reply = await socket.command(`c${i}`, { kind: "next" });
    if (String(reply.reason ?? "").startsWith("Record the participant's answer"))
      await socket.command(`a${i}`, { kind: "answer", actionId: question.id, optionId: options[answer]!.id });
    else if (reply.type === "rejected") await new Promise((r) => setTimeout(r, 150));
    else if (pauseMs) await new Promise((r) => setTimeout(r, pauseMs));
    completed = socket.messages.some((m) =>
      ((m.events as Array<{ type: string }> | undefined) ?? []).some((e) => e.type === "trial.completed"),
    );
  }
  socket.close();
  expect(completed, `the trial did not complete: ${JSON.stringify(socket.messages.slice(-6))}`).toBe(true);
  return socket.messages;
}

/** Runs the trial open in a wizard's page to its end the way a wizard does: N for the next action, 1 for the first answer. */
export async function runToTheEndInPage(wizard: Page) {
  const status = wizard.getByTestId("trial-status");
  for (let i = 0; i < 120 && (await status.textContent()) !== "completed"; i++) {
    if (await wizard.getByText("What did the participant answer?").isVisible()) await wizard.keyboard.press("1");
    else await wizard.keyboard.press("n");
    await wizard.waitForTimeout(250);
  }
  expect(await status.textContent()).toBe("completed");
}
