// A session run with its observers blind to condition, end to end through the
// real app and runtime: the observer watches the whole trial live over their
// own connection, and no tRPC response and no socket message they receive
// names or identifies the condition or its experiment.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";
import { blindedSession } from "../support/blinded-session";
import { runWholeTrial } from "../support/run-trial";
import { connectTrial } from "../support/socket";

describe.sequential("an observer blind to condition", () => {
  let app: RunningApp;
  beforeAll(async () => {
    app = await startApp();
  });
  afterAll(async () => app?.stop());

  it("watches a whole trial and never receives the condition's name or ids", async () => {
    const { studyId, secrets } = await blindedSession(app, {
      conditionsFromObservers: true,
    });

    const wizard = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const heard: string[] = [];
    const observer = apiClient(app.url, await signIn(app.url, "observer@demo.hristudio", DEMO_PASSWORD), heard);
    await observer.studies.mine.query();
    await observer.studies.get.query({ studyId });
    await observer.participants.list.query({ studyId });
    await observer.sessions.list.query({ studyId });
    await expect(observer.experiments.list.query({ studyId })).rejects.toMatchObject({ data: { code: "FORBIDDEN" } });
    await expect(observer.conditions.list.query({ studyId })).rejects.toMatchObject({ data: { code: "FORBIDDEN" } });
    const [session] = await wizard.sessions.mine.query();
    const { trialId } = await wizard.sessions.start.mutate({ sessionId: session!.id });
    await observer.trials.get.query({ trialId });
    await observer.trials.list.query({ studyId });
    await observer.coding.forTrial.query({ trialId });

    // The observer watches the whole protocol live, over their own connection.
    const { url, token } = await observer.trials.socketToken.mutate({ trialId });
    const watching = await connectTrial(url, token);
    await runWholeTrial(wizard, trialId);
    await watching.next((m) =>
      ((m.events as Array<{ type: string }> | undefined) ?? []).some((e) => e.type === "trial.completed"),
    );
    watching.close();
    await observer.trials.get.query({ trialId });

    const everything = [...heard, ...watching.messages.map((m) => JSON.stringify(m))].join("\n");
    expect(heard.length).toBeGreaterThan(8);
    expect(watching.messages.length).toBeGreaterThan(5);
    expect(secrets.filter((s) => everything.includes(s))).toEqual([]);
  }, 120_000);
});
