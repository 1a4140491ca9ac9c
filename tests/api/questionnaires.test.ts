// Questionnaires end to end on the server: versions, one-time links (reuse,
// expiry, another study), drafts kept across reloads, scores computed on the
// server, digital consent feeding the consent gate, and the CSV export.
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { questionnaireLinks } from "../../src/store/schema";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
// The participant: no account at all.
const participant = f.api("anonymous").form;
afterAll(close);

const SUS = Object.fromEntries([4, 2, 3, 4, 3, 1, 3, 3, 3, 2].map((v, i) => [`sus${i + 1}`, v]));

async function studyWithSus() {
  const study = await f.newStudy();
  const q = await owner.questionnaires.create({ studyId: study.id, instrument: "sus" });
  await owner.questionnaires.publish({ questionnaireId: q.id });
  const p = await owner.participants.create({
    studyId: study.id,
    code: "P001",
    consentStatus: "given",
    consentDate: new Date(),
  });
  return { study, q, p };
}

describe("questionnaire versions", () => {
  it("numbers each publication, and answers point at the version that was shown", async () => {
    const { q, p } = await studyWithSus();
    const first = await owner.questionnaires.createLink({ questionnaireId: q.id, participantId: p.id });
    const draft = (await owner.questionnaires.get({ questionnaireId: q.id })).draft;
    await owner.questionnaires.save({
      questionnaireId: q.id,
      definition: { ...draft, instructions: "Rate the robot's storytelling." },
    });
    expect(await owner.questionnaires.publish({ questionnaireId: q.id })).toMatchObject({ version: 2 });
    expect(first.version).toBe(1);
    expect((await participant.open({ token: first.token })).definition.instructions).not.toBe(
      "Rate the robot's storytelling.",
    );
    const second = await owner.questionnaires.createLink({ questionnaireId: q.id, participantId: p.id });
    expect(second.version).toBe(2);
    expect((await participant.open({ token: second.token })).definition.instructions).toBe(
      "Rate the robot's storytelling.",
    );
  });

  it("refuses a broken definition, naming the place", async () => {
    const { q } = await studyWithSus();
    const draft = (await owner.questionnaires.get({ questionnaireId: q.id })).draft;
    const broken = {
      ...draft,
      sections: [
        { ...draft.sections[0]!, items: [{ ...draft.sections[0]!.items[0]!, kind: "single", options: ["only one"] }] },
      ],
    };
    await expect(owner.questionnaires.save({ questionnaireId: q.id, definition: broken })).rejects.toMatchObject({
      message: "Please correct: definition.sections.0.items.0.options: needs at least 2 options",
    });
  });
});

describe("the answers CSV, in long form", () => {
  it("gives each Godspeed answer its condition and published sub-scale, and scores only the sub-scales", async () => {
    const study = await f.newStudy();
    const { experiment, version } = await publishedVersion(owner, study.id);
    const condition = await owner.conditions.create({
      studyId: study.id,
      name: "Gestures",
      experimentId: experiment.id,
    });
    const q = await owner.questionnaires.create({ studyId: study.id, instrument: "godspeed" });
    await owner.questionnaires.publish({ questionnaireId: q.id });
    const p = await owner.participants.create({
      studyId: study.id,
      code: "P007",
      consentStatus: "given",
      consentDate: new Date(),
    });
    await owner.conditions.assign({ participantId: p.id, conditionId: condition.id });
    const trial = await owner.trials.create({ versionId: version.id, participantId: p.id });
    const { token } = await owner.questionnaires.createLink({
      questionnaireId: q.id,
      participantId: p.id,
      trialId: trial.id,
    });
    // Anthropomorphism 2s, animacy 3s, likeability 4s, perceived intelligence 5s, perceived safety 1, 2, 3.
    const given = [...Array(5).fill(2), ...Array(6).fill(3), ...Array(5).fill(4), ...Array(5).fill(5), 1, 2, 3];
    await participant.submit({ token, answers: Object.fromEntries(given.map((v, i) => [`gs${i + 1}`, v])) });
    const [header, ...rows] = parseCsv((await owner.questionnaires.exportCsv({ studyId: study.id })).body);
    const named = rows.map((r) => Object.fromEntries(header!.map((c, i) => [c, r[i]])));
    expect(named).toHaveLength(24 + 5);
    expect(named[0]).toEqual({
      participant: "P007",
      condition: "Gestures",
      trial_id: trial.id,
      questionnaire: "Godspeed questionnaire",
      instrument: "Godspeed questionnaire",
      version: "1",
      measure: "answer",
      item_id: "gs1",
      item: "Fake – Natural",
      subscale: "Anthropomorphism",
      reverse_scored: "false",
      answer: "2",
    });
    expect(named[23]).toMatchObject({ item_id: "gs24", subscale: "Perceived Safety", answer: "3" });
    // No overall "Godspeed" score: the instrument defines none.
    expect(named.filter((r) => r.measure === "score").map((r) => [r.item, r.subscale, r.answer])).toEqual([
      ["Anthropomorphism", "Anthropomorphism", "2"],
      ["Animacy", "Animacy", "3"],
      ["Likeability", "Likeability", "4"],
      ["Perceived Intelligence", "Perceived Intelligence", "5"],
      ["Perceived Safety", "Perceived Safety", "2"],
    ]);
    // The study's table of trials shows the same five, by the same names.
    const [listed] = await owner.trials.list({ studyId: study.id });
    expect(listed!.scores).toEqual([
      { name: "Godspeed questionnaire · Anthropomorphism", score: 2 },
      { name: "Godspeed questionnaire · Animacy", score: 3 },
      { name: "Godspeed questionnaire · Likeability", score: 4 },
      { name: "Godspeed questionnaire · Perceived Intelligence", score: 5 },
      { name: "Godspeed questionnaire · Perceived Safety", score: 2 },
    ]);
    // Scores are results: the wizard, who may not read the data, sees the trial without them.
    const [asWizard] = await f.api("wizard").trials.list({ studyId: study.id });
    expect(asWizard).toMatchObject({ id: listed!.id, scores: [] });
  });
});

describe("one-time links", () => {
  it("keeps a draft across reloads, scores on submit, and refuses the link afterwards", async () => {
    const { study, q, p } = await studyWithSus();
    const { token } = await owner.questionnaires.createLink({ questionnaireId: q.id, participantId: p.id });
    await participant.save({ token, answers: { sus1: 4, sus2: 2 } });
    expect((await participant.open({ token })).answers).toEqual({ sus1: 4, sus2: 2 });
    await expect(participant.submit({ token, answers: { sus1: 4 } })).rejects.toMatchObject({
      code: "BAD_REQUEST",
      message: expect.stringMatching(/^Please check: I found the system unnecessarily complex\.: please answer/),
    });
    expect(await participant.submit({ token, answers: SUS })).toEqual({ submitted: true, score: 60 });
    const used = { code: "FORBIDDEN", message: expect.stringMatching(/already been submitted with this link/) };
    await expect(participant.open({ token })).rejects.toMatchObject(used);
    await expect(participant.submit({ token, answers: SUS })).rejects.toMatchObject(used);
    const csv = (await owner.questionnaires.exportCsv({ studyId: study.id })).body.split("\r\n");
    expect(csv[0]).toBe(
      "participant,condition,trial_id,questionnaire,instrument,version,measure,item_id,item,subscale,reverse_scored,answer",
    );
    const sus = "P001,,,System Usability Scale (SUS),System Usability Scale (SUS),1";
    expect(csv).toContain(`${sus},answer,sus1,I think that I would like to use this system frequently.,,false,4`);
    expect(csv).toContain(`${sus},answer,sus2,I found the system unnecessarily complex.,,true,2`);
    expect(csv).toContain(`${sus},score,,SUS score,,,60`);
  });

  it("refuses an expired link and a made-up one, and never makes a link for another study's participant", async () => {
    const { q, p } = await studyWithSus();
    const { token } = await owner.questionnaires.createLink({
      questionnaireId: q.id,
      participantId: p.id,
      expiresInMinutes: 1,
    });
    await db
      .update(questionnaireLinks)
      .set({ expiresAt: new Date(Date.now() - 1000) })
      .where(eq(questionnaireLinks.studyId, p.studyId));
    await expect(participant.open({ token })).rejects.toMatchObject({
      code: "FORBIDDEN",
      message: expect.stringMatching(/^This link expired at .* UTC\. Please ask the researcher for a new one\.$/),
    });
    await expect(participant.open({ token: "x".repeat(32) })).rejects.toMatchObject({
      code: "NOT_FOUND",
      message: "This questionnaire link is not valid. Please ask the researcher for a new one.",
    });
    const other = await studyWithSus();
    await expect(
      owner.questionnaires.createLink({ questionnaireId: q.id, participantId: other.p.id }),
    ).rejects.toMatchObject({
      code: "BAD_REQUEST",
      message: "Please correct: participantId: not a participant of this study",
    });
  });

  it("refuses answers that do not fit the questionnaire, and keeps the stored draft", async () => {
    const { q, p } = await studyWithSus();
    const { token } = await owner.questionnaires.createLink({ questionnaireId: q.id, participantId: p.id });
    await participant.save({ token, answers: { sus1: 5 } });
    await expect(participant.save({ token, answers: { sus1: 9, "<script>": "x" } })).rejects.toMatchObject({
      code: "BAD_REQUEST",
    });
    expect((await participant.open({ token })).answers).toEqual({ sus1: 5 });
  });
});

describe("digital consent", () => {
  it("records the participant's consent with the version of the text, which the trial gate then accepts", async () => {
    const study = await f.newStudy();
    const q = await owner.questionnaires.create({ studyId: study.id, name: "Consent form" });
    const draft = (await owner.questionnaires.get({ questionnaireId: q.id })).draft;
    const consentText =
      "You will hear a robot tell a story. Your answers are stored under a code, never your name. You may stop at any time.";
    await owner.questionnaires.save({
      questionnaireId: q.id,
      definition: {
        ...draft,
        sections: [
          { ...draft.sections[0]!, items: [{ id: "agree", kind: "consent", text: consentText, required: true }] },
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
    await expect(participant.submit({ token, answers: { agree: false } })).rejects.toMatchObject({
      message: expect.stringMatching(/please agree to take part/),
    });
    await participant.submit({ token, answers: { agree: true } });
    const [after] = await owner.participants.list({ studyId: study.id });
    expect(after).toMatchObject({
      consentStatus: "given",
      consentVersion: "Consent form v1",
      consentDate: expect.any(Date),
    });
  });
});
