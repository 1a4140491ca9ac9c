// Every procedure, who may call it, and an input of the fixture's study for
// it: the access rules as a person states them. The access matrix checks each
// role against it; the isolation test turns each input into another study's.
import { addAudio } from "../../src/server/media/audio";
import { schemeTemplate } from "../../src/core/coding/templates";
import { silentWav } from "../support/audio";
import { codingRows } from "../support/coding";
import { newPerson, type Caller, type Fixture } from "./fixture";

export const MEMBERS: Caller[] = ["owner", "researcher", "wizard", "observer"];
export const SIGNED_IN: Caller[] = ["owner", "researcher", "wizard", "observer", "outsider", "admin"];
const EDITORS: Caller[] = ["owner", "researcher"];
const RUNNERS: Caller[] = ["owner", "researcher", "wizard"];
const OWNER: Caller[] = ["owner"];
export const ADMIN: Caller[] = ["admin"];
export const CREATORS: Caller[] = ["owner", "researcher", "outsider", "admin"]; // system role researcher or administrator

type Input = (f: Fixture, base: Base, caller: Caller) => Promise<unknown> | unknown;
export type Base = Awaited<ReturnType<typeof baseData>>;

export async function baseData(f: Fixture) {
  const study = await f.newStudy();
  const experiment = await f.api("owner").experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
  await f.api("owner").experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "S1", actions: [{ type: "say", parameters: { text: "hi" } }] }],
  });
  const version = await f.api("owner").versions.publish({ experimentId: experiment.id });
  const participant = await f
    .api("owner")
    .participants.create({ studyId: study.id, code: "P1", consentStatus: "given", consentDate: new Date() });
  const trial = await f.api("owner").trials.create({ versionId: version.id, participantId: participant.id });
  const condition = await f
    .api("owner")
    .conditions.create({ studyId: study.id, name: "With gestures", experimentId: experiment.id });
  return { study, experiment, version, participant, trial, condition };
}

/** A code the caller marked in the base trial (a member's own), or the owner's for those who may not code. */
const ownCode = async (f: Fixture, b: Base, caller: Caller) => {
  const { schemeVersionId, codeEventId } = await codingRows(f.api("owner"), b.study.id, b.trial.id);
  const mine = await f
    .api(caller as "owner")
    .coding.addCode({ trialId: b.trial.id, schemeVersionId, setId: "intervention", codeId: "hint", startMs: 5 })
    .catch(() => ({ id: codeEventId }));
  return mine.id;
};

// Destructive procedures get fresh rows for every call.
/** A consenting participant, assigned, with a session planned for the study's wizard. */
const freshSession = async (f: Fixture, b: Base) => {
  const owner = f.api("owner");
  const p = await owner.participants.create({
    studyId: b.study.id,
    code: `S${crypto.randomUUID().slice(0, 8)}`,
    consentStatus: "given",
    consentDate: new Date(),
  });
  await owner.conditions.assign({ participantId: p.id, conditionId: b.condition.id });
  return owner.sessions.schedule({ participantId: p.id, plannedAt: new Date(), wizardId: f.people.wizard.id });
};

/** A robot of its own for each call, available to the fixture's study. */
const robotInput = (b: Base) => ({
  name: `NAO ${crypto.randomUUID().slice(0, 8)}`,
  pluginRobotId: "nao6-ros2",
  rosbridgeUrl: "ws://192.0.2.10:9090",
  sshHost: "192.0.2.10",
  sshUser: "nao",
  sshSecret: "env:HRI_ROBOT_SECRET_NAO",
  studyIds: [b.study.id],
});

/** Each publish gets an experiment of its own, so the base experiment keeps the one version the other rows use. */
const publishable = async (f: Fixture, b: Base) => {
  const e = await f.api("owner").experiments.create({ studyId: b.study.id, name: "tmp", robotId: "nao6-ros2" });
  await f.api("owner").experiments.saveDesign({
    experimentId: e.id,
    baseRevision: 0,
    steps: [{ name: "S", actions: [{ type: "wave" }] }],
  });
  return e;
};
/** A published SUS in the base study, and a fresh one-time link to it for the base participant. */
const freshLink = async (f: Fixture, b: Base) => {
  const owner = f.api("owner");
  const q = await owner.questionnaires.create({ studyId: b.study.id, instrument: "sus" });
  await owner.questionnaires.publish({ questionnaireId: q.id });
  return owner.questionnaires.createLink({
    questionnaireId: q.id,
    participantId: b.participant.id,
    trialId: b.trial.id,
  });
};
/** A recording of the base trial with one part stored, and (when asked) finished. */
const freshRecording = async (f: Fixture, b: Base, finished = false) => {
  const { recordingId } = await f
    .api("owner")
    .recordings.start({ trialId: b.trial.id, kind: "video", mimeType: "video/mp4" });
  await f.media.storage.put(`recordings/${recordingId}/chunk-000000`, new Uint8Array([1, 2, 3]), "video/mp4");
  if (finished) await f.api("owner").recordings.finish({ recordingId, durationMs: 1000 });
  return { recordingId };
};
/** A sound added to the base study by its owner, as the upload route adds one. */
export const freshAudio = async (f: Fixture, studyId: string, ownerId: string) => {
  const added = await addAudio(f.db, f.media.storage, {
    studyId,
    userId: ownerId,
    name: "chime.wav",
    bytes: silentWav(20),
  });
  if (!added.ok) throw new Error(added.reason);
  return { audioFileId: added.audio.id };
};
const EVERYONE: Caller[] = [...SIGNED_IN, "anonymous"];
const sus = Object.fromEntries([4, 2, 3, 4, 3, 1, 3, 3, 3, 2].map((v, i) => [`sus${i + 1}`, v]));

const freshMember = async (f: Fixture, b: Base) => {
  const person = await newPerson(f.db, "member");
  await f.api("owner").members.add({ studyId: b.study.id, email: person.email, role: "observer" });
  return person;
};

/** A study whose data the caller may read (the base study, or a new one they observe), for a token. */
const readableStudyFor = async (f: Fixture, b: Base, caller: Caller) => {
  if (caller === "owner" || caller === "researcher" || caller === "observer") return b.study.id;
  const study = await f.api("owner").studies.create({ title: "Readable" });
  if (caller !== "anonymous")
    await f.api("owner").members.add({ studyId: study.id, email: f.people[caller].email, role: "observer" });
  return study.id;
};
const tokenInput = async (f: Fixture, b: Base, caller: Caller) => ({
  name: "Nightly analysis",
  studyIds: [await readableStudyFor(f, b, caller)],
  expiresInDays: 30,
});
const DATA_READERS: Caller[] = ["owner", "researcher", "observer"];

export const MATRIX: Record<string, [Caller[], Input]> = {
  "account.me": [SIGNED_IN, () => undefined],
  "studies.mine": [SIGNED_IN, () => undefined],
  "studies.get": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "studies.create": [CREATORS, () => ({ title: "New" })],
  // Reading the template's design in it, and creating studies by the account (system role researcher or administrator).
  "studies.createFromTemplate": [EDITORS, (_f, b) => ({ studyId: b.study.id, title: "From a template" })],
  "studies.update": [OWNER, (_f, b) => ({ studyId: b.study.id, description: "changed" })],
  "studies.figures": [["owner", "researcher", "observer"], (_f, b) => ({ studyId: b.study.id })],
  "studies.exportArchive": [["owner", "researcher", "observer"], (_f, b) => ({ studyId: b.study.id })],
  "studies.methods": [["owner", "researcher", "observer"], (_f, b) => ({ studyId: b.study.id })],
  "studies.resultsByCondition": [["owner", "researcher", "observer"], (_f, b) => ({ studyId: b.study.id })],
  "studies.resultsByConditionCsv": [["owner", "researcher", "observer"], (_f, b) => ({ studyId: b.study.id })],
  "studies.delete": [OWNER, async (f) => ({ studyId: (await f.newStudy("Doomed")).id, confirmTitle: "Doomed" })],
  "members.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "members.add": [
    OWNER,
    async (f, b) => ({ studyId: b.study.id, email: (await newPerson(f.db, "invitee")).email, role: "observer" }),
  ],
  "members.changeRole": [
    OWNER,
    async (f, b) => ({ studyId: b.study.id, userId: (await freshMember(f, b)).id, role: "wizard" }),
  ],
  "members.remove": [OWNER, async (f, b) => ({ studyId: b.study.id, userId: (await freshMember(f, b)).id })],
  "experiments.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "experiments.get": [MEMBERS, (_f, b) => ({ experimentId: b.experiment.id })],
  "experiments.create": [EDITORS, (_f, b) => ({ studyId: b.study.id, name: "E2", robotId: "nao6-ros2" })],
  "experiments.saveDesign": [
    EDITORS,
    async (f, b) => {
      const e = await f.api("owner").experiments.create({ studyId: b.study.id, name: "tmp", robotId: "x" });
      return { experimentId: e.id, baseRevision: 0, steps: [{ name: "Only", actions: [] }] };
    },
  ],
  "experiments.choosePlugin": [EDITORS, (_f, b) => ({ experimentId: b.experiment.id, source: "first-party" })],
  "versions.publish": [EDITORS, async (f, b) => ({ experimentId: (await publishable(f, b)).id })],
  "versions.diff": [MEMBERS, (_f, b) => ({ experimentId: b.experiment.id, from: 1, to: 1 })],
  "experiments.exportFile": [MEMBERS, (_f, b) => ({ experimentId: b.experiment.id })],
  // Into another study where every study-role caller has the same role: reading the source, designing there.
  "experiments.duplicate": [
    EDITORS,
    async (f, b) => ({ experimentId: b.experiment.id, intoStudyId: (await f.newStudy("Into")).id }),
  ],
  "experiments.importFile": [
    EDITORS,
    async (f, b) => ({
      studyId: b.study.id,
      text: (await f.api("owner").experiments.exportFile({ experimentId: b.experiment.id })).text,
    }),
  ],
  "versions.list": [MEMBERS, (_f, b) => ({ experimentId: b.experiment.id })],
  "versions.get": [MEMBERS, (_f, b) => ({ versionId: b.version.id })],
  "versions.methods": [MEMBERS, (_f, b) => ({ versionId: b.version.id })],
  "participants.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "participants.create": [EDITORS, (_f, b) => ({ studyId: b.study.id, code: `P-${crypto.randomUUID().slice(0, 6)}` })],
  "participants.update": [EDITORS, (_f, b) => ({ participantId: b.participant.id, notes: "seen" })],
  "participants.reinstate": [
    OWNER,
    async (f, b) => {
      const p = await f.api("owner").participants.create({
        studyId: b.study.id,
        code: `W-${crypto.randomUUID().slice(0, 6)}`,
        consentStatus: "withdrawn",
      });
      return { participantId: p.id, reason: "recorded by mistake" };
    },
  ],
  "plugins.list": [SIGNED_IN, () => undefined],
  "plugins.get": [SIGNED_IN, () => ({ robotId: "nao6-ros2" })],
  "plugins.repositories.list": [ADMIN, () => undefined],
  "plugins.repositories.add": [ADMIN, () => ({ url: `http://127.0.0.1:9/${crypto.randomUUID()}/` })],
  "plugins.repositories.remove": [
    ADMIN,
    async (f) => ({
      repositoryId: (
        await f.api("admin").plugins.repositories.add({ url: `http://127.0.0.1:9/${crypto.randomUUID()}/` })
      ).id,
    }),
  ],
  "plugins.repositories.sync": [
    ADMIN,
    async (f) => ({
      repositoryId: (
        await f.api("admin").plugins.repositories.add({ url: `http://127.0.0.1:9/${crypto.randomUUID()}/` })
      ).id,
    }),
  ],
  "conditions.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "conditions.create": [
    EDITORS,
    (_f, b) => ({ studyId: b.study.id, name: `C-${crypto.randomUUID().slice(0, 6)}`, experimentId: b.experiment.id }),
  ],
  "conditions.assign": [
    EDITORS,
    async (f, b) => ({
      participantId: (
        await f.api("owner").participants.create({ studyId: b.study.id, code: `A-${crypto.randomUUID().slice(0, 6)}` })
      ).id,
      conditionId: b.condition.id,
    }),
  ],
  "sessions.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "sessions.schedule": [
    EDITORS,
    async (f, b) => {
      const p = await f
        .api("owner")
        .participants.create({ studyId: b.study.id, code: `Q${crypto.randomUUID().slice(0, 8)}` });
      await f.api("owner").conditions.assign({ participantId: p.id, conditionId: b.condition.id });
      return { participantId: p.id, plannedAt: new Date(), wizardId: f.people.wizard.id };
    },
  ],
  "sessions.remove": [EDITORS, async (f, b) => ({ sessionId: (await freshSession(f, b)).id })],
  "sessions.mine": [SIGNED_IN, () => undefined],
  "sessions.start": [RUNNERS, async (f, b) => ({ sessionId: (await freshSession(f, b)).id })],
  "questionnaires.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "questionnaires.get": [
    MEMBERS,
    async (f, b) => ({
      questionnaireId: (await f.api("owner").questionnaires.create({ studyId: b.study.id, instrument: "sus" })).id,
    }),
  ],
  "questionnaires.create": [EDITORS, (_f, b) => ({ studyId: b.study.id, name: "Recall" })],
  "questionnaires.save": [
    EDITORS,
    async (f, b) => ({
      questionnaireId: (await f.api("owner").questionnaires.create({ studyId: b.study.id, instrument: "sus" })).id,
      timing: "after",
    }),
  ],
  "questionnaires.publish": [
    EDITORS,
    async (f, b) => ({
      questionnaireId: (await f.api("owner").questionnaires.create({ studyId: b.study.id, instrument: "sus" })).id,
    }),
  ],
  "questionnaires.createLink": [
    RUNNERS,
    async (f, b) => {
      const q = await f.api("owner").questionnaires.create({ studyId: b.study.id, instrument: "sus" });
      await f.api("owner").questionnaires.publish({ questionnaireId: q.id });
      return { questionnaireId: q.id, participantId: b.participant.id };
    },
  ],
  "questionnaires.responses": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id })],
  "questionnaires.exportCsv": [["owner", "researcher", "observer"], (_f, b) => ({ studyId: b.study.id })],
  "coding.schemes": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "coding.scheme": [
    MEMBERS,
    async (f, b) => ({ codingSchemeId: (await codingRows(f.api("owner"), b.study.id, b.trial.id)).codingSchemeId }),
  ],
  "coding.createScheme": [EDITORS, (_f, b) => ({ studyId: b.study.id, template: "participant-engagement" })],
  "coding.saveScheme": [
    EDITORS,
    async (f, b) => ({
      codingSchemeId: (await f.api("owner").coding.createScheme({ studyId: b.study.id })).id,
      definition: schemeTemplate("wizard-interventions"),
    }),
  ],
  "coding.publishScheme": [
    EDITORS,
    async (f, b) => ({ codingSchemeId: (await f.api("owner").coding.createScheme({ studyId: b.study.id })).id }),
  ],
  "coding.forTrial": [MEMBERS, (_f, b) => ({ trialId: b.trial.id })],
  "coding.codes": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id })],
  "coding.agreement": [
    ["owner", "researcher", "observer"],
    async (f, b) => ({ schemeVersionId: (await codingRows(f.api("owner"), b.study.id, b.trial.id)).schemeVersionId }),
  ],
  "coding.keepCounted": [
    EDITORS,
    async (f, b) => ({
      codingSchemeId: (await f.api("owner").coding.createScheme({ studyId: b.study.id })).id,
      counted: { sliceMs: 1000, window: "bothCoding", stepIds: [] },
    }),
  ],
  "coding.addCode": [
    MEMBERS,
    async (f, b) => ({
      trialId: b.trial.id,
      schemeVersionId: (await codingRows(f.api("owner"), b.study.id, b.trial.id)).schemeVersionId,
      setId: "intervention",
      codeId: "guidance",
      startMs: 2000,
    }),
  ],
  // Each caller moves and deletes a code of their own tier; another observer's is refused (tests/api/coding.test.ts).
  "coding.moveCode": [MEMBERS, async (f, b, caller) => ({ codeEventId: await ownCode(f, b, caller), startMs: 10 })],
  "coding.deleteCode": [MEMBERS, async (f, b, caller) => ({ codeEventId: await ownCode(f, b, caller) })],
  // The one-time link is the participant's credential: no account needed, none checked.
  "form.open": [EVERYONE, async (f, b) => ({ token: (await freshLink(f, b)).token })],
  "form.save": [EVERYONE, async (f, b) => ({ token: (await freshLink(f, b)).token, answers: { sus1: 3 } })],
  "form.submit": [EVERYONE, async (f, b) => ({ token: (await freshLink(f, b)).token, answers: sus })],
  "recordings.start": [
    RUNNERS,
    (_f, b) => ({ trialId: b.trial.id, kind: "video", mimeType: "video/webm;codecs=vp8,opus" }),
  ],
  "recordings.setOffset": [RUNNERS, async (f, b) => ({ ...(await freshRecording(f, b)), offsetMs: 120 })],
  "recordings.chunkTarget": [RUNNERS, async (f, b) => freshRecording(f, b)],
  "recordings.finish": [RUNNERS, async (f, b) => ({ ...(await freshRecording(f, b)), durationMs: 1000 })],
  "audio.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "audio.uploadTarget": [EDITORS, (_f, b) => ({ studyId: b.study.id })],
  "audio.remove": [EDITORS, (f, b) => freshAudio(f, b.study.id, f.people.owner.id)],
  "audio.media": [RUNNERS, (f, b) => freshAudio(f, b.study.id, f.people.owner.id)],
  "recordings.cutOff": [RUNNERS, (_f, b) => ({ trialId: b.trial.id })],
  "recordings.list": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id })],
  "recordings.media": [["owner", "researcher", "observer"], async (f, b) => freshRecording(f, b, true)],
  "trials.annotate": [MEMBERS, (_f, b) => ({ trialId: b.trial.id, relMs: 1500, label: "Smiled" })],
  // Each caller edits a moment they marked themselves; others' moments are the owner's and researchers' to edit (tested in analysis.test).
  "trials.editAnnotation": [
    MEMBERS,
    async (f, b, caller) => ({
      annotationId: (
        await f
          .api(caller as "owner")
          .trials.annotate({ trialId: b.trial.id, relMs: 10, label: "Mine" })
          .catch(() => ({ id: b.trial.id }))
      ).id,
      label: "Edited",
      note: "",
    }),
  ],
  "trials.create": [RUNNERS, (_f, b) => ({ versionId: b.version.id, participantId: b.participant.id })],
  "trials.rehearse": [RUNNERS, (_f, b) => ({ experimentId: b.experiment.id })],
  "trials.liveNow": [SIGNED_IN, () => undefined],
  "trials.list": [MEMBERS, (_f, b) => ({ studyId: b.study.id })],
  "trials.get": [MEMBERS, (_f, b) => ({ trialId: b.trial.id })],
  "trials.socketToken": [MEMBERS, (_f, b) => ({ trialId: b.trial.id })],
  "trials.annotations": [MEMBERS, (_f, b) => ({ trialId: b.trial.id })],
  "trials.events": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id })],
  "trials.eventsJson": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id })],
  "trials.export": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id, format: "json" })],
  "trials.samples": [["owner", "researcher", "observer"], (_f, b) => ({ trialId: b.trial.id })],
  "admin.users.list": [ADMIN, () => undefined],
  "admin.users.create": [
    ADMIN,
    () => ({
      name: "New person",
      email: `new-${crypto.randomUUID().slice(0, 8)}@example.org`,
      password: "password-123",
      role: "observer",
    }),
  ],
  "admin.users.setRole": [ADMIN, async (f) => ({ userId: (await newPerson(f.db, "promoted")).id, role: "wizard" })],
  "admin.users.setDisabled": [ADMIN, async (f) => ({ userId: (await newPerson(f.db, "disabled")).id, disabled: true })],
  "admin.auditLog": [ADMIN, () => ({ limit: 10 })],
  "robots.list": [ADMIN, () => undefined],
  "robots.studies": [ADMIN, () => undefined],
  "robots.secretNames": [ADMIN, () => undefined],
  "robots.register": [ADMIN, (_f, b) => robotInput(b)],
  "robots.update": [
    ADMIN,
    async (f, b) => ({ ...robotInput(b), robotId: (await f.api("admin").robots.register(robotInput(b))).id }),
  ],
  "robots.remove": [ADMIN, async (f, b) => ({ robotId: (await f.api("admin").robots.register(robotInput(b))).id })],
  "tokens.studies": [SIGNED_IN, () => undefined],
  "tokens.list": [SIGNED_IN, () => undefined],
  "tokens.create": [SIGNED_IN, tokenInput],
  "tokens.revoke": [
    SIGNED_IN,
    async (f, b, caller) => {
      const holder = caller === "anonymous" ? "owner" : caller;
      return { tokenId: (await f.api(holder).tokens.create(await tokenInput(f, b, holder))).id };
    },
  ],
  "analysis.studies": [SIGNED_IN, () => undefined],
  "analysis.trials": [DATA_READERS, (_f, b) => ({ studyId: b.study.id })],
  "analysis.events": [DATA_READERS, (_f, b) => ({ studyId: b.study.id })],
  "analysis.samples": [DATA_READERS, (_f, b) => ({ studyId: b.study.id })],
  "analysis.answers": [DATA_READERS, (_f, b) => ({ studyId: b.study.id })],
  "analysis.annotations": [DATA_READERS, (_f, b) => ({ studyId: b.study.id })],
  "analysis.codes": [DATA_READERS, (_f, b) => ({ studyId: b.study.id })],
  "analysis.trialEvents": [DATA_READERS, (_f, b) => ({ trialId: b.trial.id })],
};
