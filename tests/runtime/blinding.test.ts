// A double-blind session, end to end through the real app and runtime: the
// blinded wizard runs a whole Storyteller trial from "My sessions", and no
// tRPC response and no socket message they receive names or identifies the
// condition or its experiment.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";
import { blindedSession } from "../support/blinded-session";
import { runWholeTrial } from "../support/run-trial";

describe.sequential("a blinded wizard", () => {
  let app: RunningApp;
  beforeAll(async () => {
    app = await startApp();
  });
  afterAll(async () => app?.stop());

  it("runs a whole trial and never receives the condition's name or ids", async () => {
    const { researcher, studyId, condition, gestures, secrets } = await blindedSession(app, {
      conditionsFromWizards: true,
      resultsUntilComplete: false,
    });

    const heard: string[] = [];
    const wizard = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD), heard);
    await wizard.account.me.query();
    await wizard.studies.mine.query();
    await wizard.studies.get.query({ studyId });
    await wizard.participants.list.query({ studyId });
    await wizard.sessions.list.query({ studyId });
    const [session] = await wizard.sessions.mine.query();
    expect(session).toMatchObject({ participantCode: "B001", conditionName: null });
    await expect(wizard.experiments.list.query({ studyId })).rejects.toMatchObject({ data: { code: "FORBIDDEN" } });
    await expect(wizard.conditions.list.query({ studyId })).rejects.toMatchObject({ data: { code: "FORBIDDEN" } });
    const { trialId } = await wizard.sessions.start.mutate({ sessionId: session!.id });
    await wizard.trials.get.query({ trialId });
    await wizard.trials.list.query({ studyId });

    // The whole protocol, as the wizard's N key and answer buttons would run it.
    const socketMessages = await runWholeTrial(wizard, trialId);
    await wizard.trials.get.query({ trialId });

    const everything = [...heard, ...socketMessages.map((m) => JSON.stringify(m))].join("\n");
    expect(heard.length).toBeGreaterThan(10);
    expect(secrets.filter((s) => everything.includes(s))).toEqual([]);

    // The researcher still sees it all, and lifting the blind is on the record.
    expect((await researcher.sessions.list.query({ studyId }))[0]).toMatchObject({
      conditionName: condition.name,
      trialId,
    });
    await researcher.studies.update.mutate({
      studyId,
      settings: { blinding: { conditionsFromWizards: false, resultsUntilComplete: false } },
    });
    expect((await wizard.trials.get.query({ trialId })).experimentName).toBe(
      condition === gestures ? "Gestured telling ZK4" : "Voice-only telling QX7",
    );
  }, 120_000);
});
