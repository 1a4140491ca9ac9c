// A study that has run: settings away from their defaults, two experiments
// (one published, one a draft), two conditions, two questionnaires (one
// published and answered), and the data of a run: participants, a session, a
// trial with events and robot samples, an annotation, a finished recording.
// For showing what a copy of its design leaves behind.
import { appendEvents } from "../../src/store/event-store";
import { trialSamples } from "../../src/store/schema";
import type { Fixture } from "./fixture";

const SUS = Object.fromEntries([4, 2, 4, 2, 4, 2, 4, 2, 4, 2].map((v, i) => [`sus${i + 1}`, v]));

export async function fullStudy(f: Fixture) {
  const owner = f.api("owner");
  const study = await f.newStudy("Storytelling and memory");
  await owner.studies.update({
    studyId: study.id,
    description: "Does the way a robot tells a story change what a listener remembers?",
    settings: {
      requireConsent: true,
      assignment: { strategy: "balanced", perCondition: 2 },
      blinding: { resultsUntilComplete: true },
      demographics: [
        { key: "experience", label: "Programming experience", type: "choice", options: ["none", "some", "lots"] },
      ],
      consentDocumentVersion: "2b",
    },
  });
  const gestures = await owner.experiments.create({
    studyId: study.id,
    name: "Story with gestures",
    robotId: "nao6-ros2",
  });
  await owner.experiments.saveDesign({
    experimentId: gestures.id,
    baseRevision: 0,
    steps: [
      { name: "Greeting", actions: [{ type: "say", parameters: { text: "Hello, I am NAO." } }, { type: "wave" }] },
      { name: "Story", actions: [{ type: "say", parameters: { text: "Once upon a time…" } }] },
    ],
  });
  const version = await owner.versions.publish({ experimentId: gestures.id });
  const still = await owner.experiments.create({
    studyId: study.id,
    name: "Story standing still",
    robotId: "nao6-ros2",
  });
  await owner.experiments.saveDesign({
    experimentId: still.id,
    baseRevision: 0,
    steps: [{ name: "Story", actions: [{ type: "say", parameters: { text: "Once upon a time…" } }] }],
  });
  const withGestures = await owner.conditions.create({
    studyId: study.id,
    name: "With gestures",
    description: "The robot waves",
    experimentId: gestures.id,
  });
  await owner.conditions.create({ studyId: study.id, name: "Standing still", experimentId: still.id });
  const sus = await owner.questionnaires.create({ studyId: study.id, instrument: "sus" });
  await owner.questionnaires.save({ questionnaireId: sus.id, timing: "after" });
  await owner.questionnaires.publish({ questionnaireId: sus.id });
  await owner.questionnaires.create({ studyId: study.id, name: "Story recall" });

  // The run.
  const participant = await owner.participants.create({
    studyId: study.id,
    code: "P01",
    consentStatus: "given",
    consentDate: new Date(),
    demographics: { experience: "some" },
  });
  await owner.participants.create({ studyId: study.id, code: "P02" });
  await owner.conditions.assign({ participantId: participant.id, conditionId: withGestures.id });
  await owner.sessions.schedule({ participantId: participant.id, plannedAt: new Date(), wizardId: f.people.wizard.id });
  const trial = await owner.trials.create({ versionId: version.id, participantId: participant.id });
  await appendEvents(
    f.db,
    { id: trial.id, lastSeq: 0, t0: null },
    [{ type: "trial.started" }, { type: "note.added", text: "Participant laughed" }],
    f.people.owner.id,
  );
  await f.db
    .insert(trialSamples)
    .values({ trialId: trial.id, topic: "/joint_states", relMs: 20, data: { position: [1] } });
  await owner.trials.annotate({ trialId: trial.id, relMs: 1500, label: "Smiled" });
  const { recordingId } = await owner.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
  await f.media.storage.put(`recordings/${recordingId}/chunk-000000`, new Uint8Array([1, 2, 3]), "video/mp4");
  await owner.recordings.finish({ recordingId, durationMs: 1000 });
  const link = await owner.questionnaires.createLink({
    questionnaireId: sus.id,
    participantId: participant.id,
    trialId: trial.id,
  });
  await f.api("anonymous").form.submit({ token: link.token, answers: SUS });
  return { study, gestures, still, trial };
}
