// Trials with participants run only in an active study, as the overview says:
// a draft rehearses, a completed or archived study keeps its data as it is.
import { afterAll, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture, plannedSession, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

/** A study with a published experiment, a consenting participant and a session planned for the wizard. */
async function studyWithSession() {
  const study = await f.newStudy();
  const { experiment, version } = await publishedVersion(owner, study.id);
  const { participant, session } = await plannedSession(owner, study.id, experiment.id, "P1", f.people.wizard.id);
  return { study, experiment, version, participant, session };
}

it.each([
  ["draft", /still a draft: rehearse its experiments from the designer, and set the study to active/],
  ["completed", /completed: its data is kept read-only and it runs no new trials/],
  ["archived", /archived: its data is kept read-only/],
] as const)("a %s study runs no trials, from the trials tab or from a session", async (status, message) => {
  const { study, version, participant, session } = await studyWithSession();
  await owner.studies.update({ studyId: study.id, status });
  await expect(owner.trials.create({ versionId: version.id, participantId: participant.id })).rejects.toMatchObject({
    code: "PRECONDITION_FAILED",
    message: expect.stringMatching(message),
  });
  await expect(f.api("wizard").sessions.start({ sessionId: session.id })).rejects.toMatchObject({
    code: "PRECONDITION_FAILED",
    message: expect.stringMatching(message),
  });
});

it("a draft study rehearses its experiments, and runs trials once it is active", async () => {
  const { study, experiment, version, participant, session } = await studyWithSession();
  await owner.studies.update({ studyId: study.id, status: "draft" });
  await expect(owner.trials.rehearse({ experimentId: experiment.id })).resolves.toMatchObject({ isRehearsal: true });
  await owner.studies.update({ studyId: study.id, status: "active" });
  await expect(owner.trials.create({ versionId: version.id, participantId: participant.id })).resolves.toMatchObject({
    isRehearsal: false,
  });
  await expect(f.api("wizard").sessions.start({ sessionId: session.id })).resolves.toHaveProperty("trialId");
});
