// A demo study set up for a blinding test, as a research team would through
// the API: two conditions on two experiments whose names a leak would show,
// the blind the test asks for, one participant assigned and their session
// planned for the demo wizard. `secrets`: every name and id of the
// conditions and experiments, none of which a blinded person may receive.
import type { RunningApp } from "./app";
import { DEMO_PASSWORD } from "./app";
import { apiClient, signIn } from "./http";

export async function blindedSession(
  app: RunningApp,
  blinding: { conditionsFromWizards?: boolean; resultsUntilComplete?: boolean; conditionsFromObservers?: boolean },
) {
  const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
  const [study] = await researcher.studies.mine.query();
  const studyId = study!.id;
  const [storyteller] = await researcher.experiments.list.query({ studyId });
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
    settings: { assignment: { strategy: "balanced", perCondition: 1 }, blinding },
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
  return { researcher, studyId, condition, gestures, secrets };
}
