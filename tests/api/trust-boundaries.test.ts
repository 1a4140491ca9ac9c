// The smaller holes of one shared lab server, each as it was found: a
// withdrawal undone by an old consent link, the allocation seed in a blinded
// wizard's hands, a NUL character or a database error answered with SQL.
import { afterAll, describe, expect, it, vi } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
const participantForm = f.api("anonymous").form;
afterAll(close);

/** A published consent form in a fresh study, and a week-long link to it for a new participant. */
async function consentLink() {
  const study = await f.newStudy();
  const q = await owner.questionnaires.create({ studyId: study.id, name: "Consent form" });
  const draft = (await owner.questionnaires.get({ questionnaireId: q.id })).draft;
  await owner.questionnaires.save({
    questionnaireId: q.id,
    definition: {
      ...draft,
      sections: [
        { ...draft.sections[0]!, items: [{ id: "agree", kind: "consent", text: "I agree.", required: true }] },
      ],
    },
  });
  await owner.questionnaires.publish({ questionnaireId: q.id });
  const p = await owner.participants.create({ studyId: study.id, code: "C001" });
  const { token } = await owner.questionnaires.createLink({
    questionnaireId: q.id,
    participantId: p.id,
    expiresInMinutes: 60 * 24 * 7,
  });
  return { study, p, token, questionnaireId: q.id };
}

describe("withdrawal", () => {
  it("ends the participant's links: an old consent link can no longer turn it back into consent", async () => {
    const { study, p, token } = await consentLink();
    await owner.participants.update({ participantId: p.id, consentStatus: "withdrawn" });
    await expect(participantForm.open({ token })).rejects.toMatchObject({
      code: "FORBIDDEN",
      message: expect.stringMatching(/withdrawn from this study/),
    });
    await expect(participantForm.submit({ token, answers: { agree: true } })).rejects.toMatchObject({
      code: "FORBIDDEN",
    });
    const [after] = await owner.participants.list({ studyId: study.id });
    expect(after).toMatchObject({ consentStatus: "withdrawn" });
  });

  it("sends a withdrawn participant no new questionnaire", async () => {
    const { p, questionnaireId } = await consentLink();
    await owner.participants.update({ participantId: p.id, consentStatus: "withdrawn" });
    await expect(owner.questionnaires.createLink({ questionnaireId, participantId: p.id })).rejects.toMatchObject({
      code: "PRECONDITION_FAILED",
    });
  });

  it("is undone only by the owner's reinstatement, with a reason on the record", async () => {
    const { study, p } = await consentLink();
    await owner.participants.update({ participantId: p.id, consentStatus: "withdrawn" });
    for (const status of ["given", "pending", "declined"] as const) {
      await expect(owner.participants.update({ participantId: p.id, consentStatus: status })).rejects.toMatchObject({
        code: "FORBIDDEN",
        message: expect.stringMatching(/Only the study's owner can reinstate/),
      });
    }
    await expect(
      f.api("researcher").participants.reinstate({ participantId: p.id, reason: "typo" }),
    ).rejects.toMatchObject({ code: "FORBIDDEN" });
    await expect(
      owner.participants.reinstate({ participantId: p.id, reason: "Withdrawal recorded for the wrong participant." }),
    ).resolves.toMatchObject({ consentStatus: "given" });
    const log = (await f.api("admin").admin.auditLog({ limit: 50 })).filter(
      (e) => e.studyId === study.id && e.action === "participant.consent.reinstated",
    );
    expect(log).toEqual([
      expect.objectContaining({
        target: p.id,
        details: expect.objectContaining({ reason: "Withdrawal recorded for the wrong participant." }),
      }),
    ]);
  });
});

describe("allocation concealment", () => {
  it("never sends the assignment seed to a wizard, blinded or not; the owner and researchers see it", async () => {
    const study = await f.newStudy();
    await owner.studies.update({
      studyId: study.id,
      settings: {
        assignment: { strategy: "random", perCondition: 1 },
        blinding: { conditionsFromWizards: true, resultsUntilComplete: false },
      },
    });
    const seed = (await owner.studies.get({ studyId: study.id })).settings.assignment.seed;
    expect(seed).toMatch(/^[0-9a-f]{24}$/);
    expect((await f.api("researcher").studies.get({ studyId: study.id })).settings.assignment.seed).toBe(seed);
    for (const caller of ["wizard", "observer"] as const) {
      const seen = await f.api(caller).studies.get({ studyId: study.id });
      expect(seen.settings.assignment.seed).toBeUndefined();
      expect(JSON.stringify(seen)).not.toContain(seed!);
    }
  });
});

describe("errors a client sees", () => {
  it("refuses a NUL character with where it is, and stores nothing", async () => {
    const study = await f.newStudy();
    const experiment = await owner.experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
    const error = await f.httpError("owner", "experiments.saveDesign", {
      experimentId: experiment.id,
      baseRevision: 0,
      steps: [{ name: "Hello", actions: [{ type: "say", parameters: { text: "Hi\u0000there" } }] }],
    });
    expect(error).toMatchObject({
      message: "Please correct: steps.0.actions.0.parameters.text: must not contain the NUL character (\\0)",
      data: { code: "BAD_REQUEST" },
    });
    expect((await owner.experiments.get({ experimentId: experiment.id })).steps).toEqual([]);
  });

  it("answers a database error with a plain sentence and a reference that is in the server's log, never SQL or a stack", async () => {
    const study = await f.newStudy();
    const logged: string[] = [];
    const spy = vi.spyOn(console, "error").mockImplementation((line: unknown) => void logged.push(String(line)));
    // A real failure of the real database: the table the procedure reads is gone for a moment.
    await db.execute("alter table annotations rename to annotations_away");
    try {
      const experiment = await owner.experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
      await owner.experiments.saveDesign({
        experimentId: experiment.id,
        baseRevision: 0,
        steps: [{ name: "S", actions: [{ type: "wave" }] }],
      });
      const version = await owner.versions.publish({ experimentId: experiment.id });
      const p = await owner.participants.create({
        studyId: study.id,
        code: "E1",
        consentStatus: "given",
        consentDate: new Date(),
      });
      const trial = await owner.trials.create({ versionId: version.id, participantId: p.id });
      const error = await f.httpError("owner", "trials.annotate", { trialId: trial.id, relMs: 1, label: "Smiled" });
      const reference = /reference ([0-9a-f]{8})/.exec(error?.message ?? "")?.[1];
      expect(error?.message).toMatch(/^Something went wrong on the server\./);
      expect(JSON.stringify(error)).not.toMatch(/select|annotations|relation|stack|\.ts:/i);
      expect(logged.some((line) => line.includes(`error ${reference}`) && /annotations/.test(line))).toBe(true);
    } finally {
      await db.execute("alter table annotations_away rename to annotations");
      spy.mockRestore();
    }
  });
});
