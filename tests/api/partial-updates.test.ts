// An update names the fields it changes; every field it leaves out stays as
// it was. Each row starts from a row with every field away from its default
// (so a default filled in would show), changes one field, and compares the
// whole row read back through the app's own procedures.
import { afterAll, describe, expect, it } from "vitest";
import { blankQuestionnaire } from "../../src/core/questionnaires/builder";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

/** What a save stamps on the row besides the change itself. */
const STAMPS = ["updatedAt", "updatedBy", "draftRevision"];
const withoutStamps = (row: object) => Object.fromEntries(Object.entries(row).filter(([k]) => !STAMPS.includes(k)));

async function fullStudy() {
  const study = await f.newStudy("Full study");
  await owner.studies.update({
    studyId: study.id,
    description: "All set",
    status: "active",
    settings: {
      requireConsent: false,
      assignment: { strategy: "balanced", perCondition: 2 },
      blinding: { conditionsFromWizards: true, resultsUntilComplete: true },
      demographics: [{ key: "age", label: "Age", type: "number", options: [] }],
      consentDocumentVersion: "2b",
    },
  });
  return study.id;
}
const readStudy = async (studyId: string) => withoutStamps(await owner.studies.get({ studyId }));

describe("studies.update changes only the fields it names", () => {
  it.each<[string, Record<string, unknown>, (before: Awaited<ReturnType<typeof owner.studies.get>>) => object]>([
    ["title", { title: "Renamed" }, () => ({ title: "Renamed" })],
    ["description", { description: "Changed" }, () => ({ description: "Changed" })],
    ["status", { status: "completed" }, () => ({ status: "completed" })],
    [
      "consent required",
      { settings: { requireConsent: true } },
      (b) => ({ settings: { ...b.settings, requireConsent: true } }),
    ],
    [
      "the wizards' blind",
      { settings: { blinding: { conditionsFromWizards: false } } },
      (b) => ({ settings: { ...b.settings, blinding: { ...b.settings.blinding, conditionsFromWizards: false } } }),
    ],
    [
      "the results' blind",
      { settings: { blinding: { resultsUntilComplete: false } } },
      (b) => ({ settings: { ...b.settings, blinding: { ...b.settings.blinding, resultsUntilComplete: false } } }),
    ],
    [
      "the consent document",
      { settings: { consentDocumentVersion: "3" } },
      (b) => ({ settings: { ...b.settings, consentDocumentVersion: "3" } }),
    ],
  ])("%s", async (_, change, changed) => {
    const studyId = await fullStudy();
    const before = await owner.studies.get({ studyId });
    await owner.studies.update({ studyId, ...change });
    expect(await readStudy(studyId)).toEqual(withoutStamps({ ...before, ...changed(before) }));
  });
});

async function fullParticipant() {
  const studyId = await fullStudy();
  const p = await owner.participants.create({
    studyId,
    code: "P-full",
    consentStatus: "given",
    consentDate: new Date("2025-03-01T10:00:00Z"),
    consentVersion: "2a",
    notes: "Came early",
    demographics: { age: 31 },
  });
  return { studyId, participantId: p.id };
}
const readParticipant = async (studyId: string, participantId: string) =>
  (await owner.participants.list({ studyId })).find((p) => p.id === participantId)!;

describe("participants.update changes only the fields it names", () => {
  it.each<[string, Record<string, unknown>]>([
    ["code", { code: "P-renamed" }],
    // Declined, not given: consent given also records the consent document's version, by design.
    ["consent status", { consentStatus: "declined" }],
    ["consent date", { consentDate: new Date("2025-04-02T09:00:00Z") }],
    ["consent version", { consentVersion: "2b" }],
    ["notes", { notes: "Rescheduled" }],
    ["demographics", { demographics: { age: 32 } }],
  ])("%s", async (_, change) => {
    const { studyId, participantId } = await fullParticipant();
    const before = await readParticipant(studyId, participantId);
    await owner.participants.update({ participantId, ...change });
    expect(await readParticipant(studyId, participantId)).toEqual({ ...before, ...change });
  });
});

async function fullQuestionnaire() {
  const studyId = await fullStudy();
  const { id } = await owner.questionnaires.create({ studyId, name: "Recall" });
  await owner.questionnaires.save({
    questionnaireId: id,
    timing: "before",
    definition: { ...blankQuestionnaire("Recall", () => "s1"), instructions: "Answer freely" },
  });
  return id;
}
const readQuestionnaire = async (questionnaireId: string) =>
  withoutStamps(await owner.questionnaires.get({ questionnaireId }));

describe("questionnaires.save changes only the fields it names", () => {
  it.each<[string, Record<string, unknown>, object]>([
    ["name", { name: "Story recall" }, { name: "Story recall" }],
    ["timing", { timing: "after" }, { timing: "after" }],
    [
      "definition",
      { definition: blankQuestionnaire("Other", () => "s2") },
      { draft: blankQuestionnaire("Other", () => "s2") },
    ],
  ])("%s", async (_, change, changed) => {
    const questionnaireId = await fullQuestionnaire();
    const before = await readQuestionnaire(questionnaireId);
    await owner.questionnaires.save({ questionnaireId, ...change });
    expect(await readQuestionnaire(questionnaireId)).toEqual({ ...before, ...changed });
  });
});

describe("the designer's save changes only the experiment details it names", () => {
  it.each<[string, Record<string, string>]>([
    ["name", { name: "Renamed" }],
    ["description", { description: "Changed" }],
    ["robot", { robotId: "pepper-ros2" }],
  ])("%s", async (_, details) => {
    const studyId = await fullStudy();
    const e = await owner.experiments.create({
      studyId,
      name: "Full",
      description: "Every field set",
      robotId: "nao6-ros2",
    });
    const before = await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [
        {
          name: "Greet",
          description: "Say hello",
          actions: [{ type: "say", name: "Hello", parameters: { text: "Hi" }, parallelGroup: "g1" }],
        },
      ],
    });
    const after = await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: before.draftRevision,
      details,
      steps: before.steps,
    });
    expect(withoutStamps(after)).toEqual(withoutStamps({ ...before, ...details }));
  });
});
