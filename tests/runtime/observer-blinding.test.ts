// A session run with its observers blind to condition, end to end through the
// real app and runtime: the observer watches the whole trial live over their
// own connection, and no tRPC response and no socket message they receive
// names or identifies the condition or its experiment.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";
import { runWholeTrial } from "../support/run-trial";
import { connectTrial } from "../support/socket";

describe.sequential("an observer blind to condition", () => {
  let app: RunningApp;
  beforeAll(async () => {
    app = await startApp();
  });
  afterAll(async () => app?.stop());

  it("watches a whole trial and never receives the condition's name or ids", async () => {
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const studyId = study!.id;
    const [storyteller] = await researcher.experiments.list.query({ studyId });
    // Two conditions on two experiments, with names a leak would show.
    const file = await researcher.experiments.exportFile.query({ experimentId: storyteller!.id });
    const voiceOnly = await researcher.experiments.importFile.mutate({
      studyId,
      text: file.text.replace('"name": "Interactive Storyteller"', '"name": "Voice-only telling QX7"'),
    });
    const draft = await researcher.experiments.get.query({ experimentId: storyteller!.id });
    await researcher.experiments.saveDesign.mutate({
      experimentId: draft.id,
      baseRevision: draft.draftRevision,
      details: { name: "Gestured telling ZK4" },
      steps: draft.steps,
    });
    for (const e of [storyteller!.id, voiceOnly.id]) await researcher.versions.publish.mutate({ experimentId: e });
    const gestures = await researcher.conditions.create.mutate({
      studyId,
      name: "Gestures-condition-RB2",
      description: "NAO waves and nods",
      experimentId: storyteller!.id,
    });
    const voice = await researcher.conditions.create.mutate({
      studyId,
      name: "Voice-condition-MW9",
      description: "speech only",
      experimentId: voiceOnly.id,
    });
    await researcher.studies.update.mutate({
      studyId,
      settings: {
        assignment: { strategy: "balanced", perCondition: 1 },
        blinding: { conditionsFromObservers: true },
      },
    });
    const participant = await researcher.participants.create.mutate({
      studyId,
      code: "B001",
      consentStatus: "given",
      consentDate: new Date(),
    });
    const assigned = await researcher.conditions.assign.mutate({ participantId: participant.id });
    const condition = [gestures, voice].find((c) => c.id === assigned.conditionId)!;
    const wizardAccount = (await researcher.members.list.query({ studyId })).find((m) => m.role === "wizard")!;
    await researcher.sessions.schedule.mutate({
      participantId: participant.id,
      plannedAt: new Date(),
      wizardId: wizardAccount.userId,
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
    const secrets = [
      condition.id,
      condition.name,
      condition.description,
      gestures.name,
      voice.name,
      storyteller!.id,
      voiceOnly.id,
      "Gestured telling ZK4",
      "Voice-only telling QX7",
    ];
    expect(heard.length).toBeGreaterThan(8);
    expect(watching.messages.length).toBeGreaterThan(5);
    expect(secrets.filter((s) => everything.includes(s))).toEqual([]);
  }, 120_000);
});
