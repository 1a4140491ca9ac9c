// A study from another as a template: the design (settings that are design,
// experiments, conditions, questionnaires) comes along, nothing of the
// source's run does (participants, sessions, trials and their events and
// samples, annotations, recordings, questionnaire links and answers, published
// versions, audit, other members), and the two are independent afterwards.
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { auditLog, experiments } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { studyFingerprint, studyRowCounts } from "../support/study-rows";
import { buildFixture, newPerson } from "./fixture";
import { schemeTemplate } from "../../src/core/coding/templates";
import { codingRows } from "../support/coding";
import { fullStudy } from "./full-study";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

const source = await fullStudy(f);
// A published coding scheme whose draft moved on since, and a code in the source's trial.
const sourceCoding = await codingRows(owner, source.study.id, source.trial.id);
await owner.coding.saveScheme({
  codingSchemeId: sourceCoding.codingSchemeId,
  definition: { ...schemeTemplate("wizard-interventions"), name: "Interventions, revised" },
});
const sourceBefore = await studyFingerprint(db, source.study.id);

/** An experiment's design with ids replaced by names, so a copy and its source compare. */
const design = async (api: typeof owner, experimentId: string) => {
  const d = await api.experiments.get({ experimentId });
  return {
    name: d.name,
    robotId: d.robotId,
    steps: d.steps.map((s) => ({ name: s.name, actions: s.actions.map((a) => [a.type, a.parameters]) })),
  };
};

describe("a study from a template", async () => {
  // A researcher of the source makes it: the new study is theirs alone.
  const researcher = f.api("researcher");
  const copy = await researcher.studies.createFromTemplate({ studyId: source.study.id, title: "Replication 2027" });

  it("is a draft with the source's description, its creator its owner and only member", async () => {
    expect(copy).toMatchObject({
      title: "Replication 2027",
      description: "Does the way a robot tells a story change what a listener remembers?",
      status: "draft",
      createdBy: f.people.researcher.id,
    });
    expect((await researcher.members.list({ studyId: copy.id })).map((m) => [m.email, m.role])).toEqual([
      [f.people.researcher.email, "owner"],
    ]);
    // The source's owner is not let in by having made the template.
    await expect(owner.studies.get({ studyId: copy.id })).rejects.toMatchObject({ code: "NOT_FOUND" });
  });

  it("carries the settings that are design, with a seed of its own and the consent document started again", async () => {
    const sourceSettings = (await owner.studies.get({ studyId: source.study.id })).settings;
    const { settings } = await researcher.studies.get({ studyId: copy.id });
    expect(settings).toMatchObject({
      requireConsent: true,
      assignment: { strategy: "balanced", perCondition: 2 },
      blinding: { conditionsFromWizards: false, resultsUntilComplete: true },
      demographics: [
        { key: "experience", label: "Programming experience", type: "choice", options: ["none", "some", "lots"] },
      ],
      consentDocumentVersion: "1",
    });
    expect(settings.assignment.seed).toMatch(/^[0-9a-f]{24}$/);
    expect(settings.assignment.seed).not.toBe(sourceSettings.assignment.seed);
  });

  it("copies every experiment's draft, unpublished, under its own name", async () => {
    const copied = await researcher.experiments.list({ studyId: copy.id });
    expect(copied.map((e) => [e.name, e.latestVersion])).toEqual([
      ["Story standing still", null],
      ["Story with gestures", null],
    ]);
    const byName = (name: string) => copied.find((e) => e.name === name)!.id;
    expect(await design(researcher, byName("Story with gestures"))).toEqual(await design(owner, source.gestures.id));
    expect(await design(researcher, byName("Story standing still"))).toEqual(await design(owner, source.still.id));
  });

  it("binds each condition to the copy of its experiment", async () => {
    const conditions = await researcher.conditions.list({ studyId: copy.id });
    expect(conditions.map((c) => [c.name, c.description, c.experimentName, c.participantCount])).toEqual([
      ["Standing still", "", "Story standing still", 0],
      ["With gestures", "The robot waves", "Story with gestures", 0],
    ]);
    for (const c of conditions) {
      const [bound] = await db.select().from(experiments).where(eq(experiments.id, c.experimentId));
      expect(bound!.studyId).toBe(copy.id);
    }
  });

  it("copies the questionnaires as drafts with their timing, unpublished", async () => {
    const listed = await researcher.questionnaires.list({ studyId: copy.id });
    expect(listed.map((q) => [q.name, q.timing, q.instrument, q.latestVersion])).toEqual([
      ["Story recall", "none", null, null],
      ["System Usability Scale (SUS)", "after", "sus", null],
    ]);
    const sourceList = await owner.questionnaires.list({ studyId: source.study.id });
    for (const q of listed) {
      const from = sourceList.find((s) => s.name === q.name)!;
      expect((await researcher.questionnaires.get({ questionnaireId: q.id })).draft).toEqual(
        (await owner.questionnaires.get({ questionnaireId: from.id })).draft,
      );
    }
  });

  it("copies the coding schemes' drafts, unpublished, and none of the source's codes", async () => {
    const listed = await researcher.coding.schemes({ studyId: copy.id });
    expect(listed.map((s) => [s.name, s.latestVersion])).toEqual([["Interventions, revised", null]]);
    expect((await researcher.coding.scheme({ codingSchemeId: listed[0]!.id })).draft).toEqual({
      ...schemeTemplate("wizard-interventions"),
      name: "Interventions, revised",
    });
  });

  it("holds nothing of the source's run: counted row by row", async () => {
    expect(await studyRowCounts(db, copy.id)).toEqual({
      study: 1,
      member: 1,
      experiment: 2,
      step: 3,
      action: 4,
      condition: 2,
      questionnaire: 2,
      "coding scheme": 1,
      // Its own creation, saying which study it came from.
      audit: 1,
    });
    const [created] = await db.select().from(auditLog).where(eq(auditLog.studyId, copy.id));
    expect(created).toMatchObject({
      action: "study.create",
      details: { template: { studyId: source.study.id, title: "Storytelling and memory" } },
    });
  });

  it("left the source exactly as it was", async () => {
    expect(await studyFingerprint(db, source.study.id)).toBe(sourceBefore);
  });

  it("is independent: changing the copy leaves the source, and changing the source leaves the copy", async () => {
    const [copiedExperiment] = (await researcher.experiments.list({ studyId: copy.id })).filter(
      (e) => e.name === "Story with gestures",
    );
    await researcher.experiments.saveDesign({
      experimentId: copiedExperiment!.id,
      baseRevision: (await researcher.experiments.get({ experimentId: copiedExperiment!.id })).draftRevision,
      steps: [{ name: "Only in the copy", actions: [{ type: "say", parameters: { text: "Changed" } }] }],
    });
    const [copiedQuestionnaire] = await researcher.questionnaires.list({ studyId: copy.id });
    await researcher.questionnaires.save({
      questionnaireId: copiedQuestionnaire!.id,
      name: "Renamed",
      timing: "before",
    });
    await researcher.studies.update({ studyId: copy.id, settings: { blinding: { resultsUntilComplete: false } } });
    expect(await studyFingerprint(db, source.study.id)).toBe(sourceBefore);

    const copyBefore = await studyFingerprint(db, copy.id);
    await owner.experiments.saveDesign({
      experimentId: source.still.id,
      baseRevision: 1,
      steps: [{ name: "Only in the source", actions: [] }],
    });
    expect(await studyFingerprint(db, copy.id)).toBe(copyBefore);
  });
});

describe("who may start from a study", () => {
  it("an observer of the source whose account may create studies may: reading the design is enough", async () => {
    const reader = await newPerson(db, "reader");
    await owner.members.add({ studyId: source.study.id, email: reader.email, role: "observer" });
    const made = await f.apiAs(reader).studies.createFromTemplate({ studyId: source.study.id, title: "Mine" });
    expect(await studyRowCounts(db, made.id)).toMatchObject({ experiment: 2, condition: 2, member: 1 });
  });

  it("refuses accounts that may not create studies, plainly", async () => {
    for (const caller of ["wizard", "observer"] as const)
      await expect(
        f.api(caller).studies.createFromTemplate({ studyId: source.study.id, title: "No" }),
      ).rejects.toMatchObject({
        code: "FORBIDDEN",
        message: expect.stringMatching(/Your account \(\w+\) may not do this/),
      });
  });

  it("refuses a study the caller is not a member of as if it did not exist, and writes nothing", async () => {
    const stranger = f.api("outsider");
    const mine = (await stranger.studies.mine()).length;
    await expect(
      stranger.studies.createFromTemplate({ studyId: source.study.id, title: "Stolen" }),
    ).rejects.toMatchObject({ code: "NOT_FOUND" });
    expect(await stranger.studies.mine()).toHaveLength(mine);
  });

  it("refuses a wizard kept blind to the conditions, even with an account that may create studies", async () => {
    const blinded = await newPerson(db, "blinded");
    const study = await f.newStudy("Blind");
    await owner.members.add({ studyId: study.id, email: blinded.email, role: "wizard" });
    await owner.studies.update({ studyId: study.id, settings: { blinding: { conditionsFromWizards: true } } });
    await expect(
      f.apiAs(blinded).studies.createFromTemplate({ studyId: study.id, title: "Peek" }),
    ).rejects.toMatchObject({ code: "FORBIDDEN", message: expect.stringContaining("blinding") });
  });

  it("makes nothing at all when one experiment cannot be copied (its robot's plugin is not installed)", async () => {
    const study = await f.newStudy("Old robot");
    await owner.experiments.create({ studyId: study.id, name: "Fine", robotId: "nao6-ros2" });
    await owner.experiments.create({ studyId: study.id, name: "Retired robot", robotId: "no-such-robot" });
    const before = (await owner.studies.mine()).length;
    await expect(owner.studies.createFromTemplate({ studyId: study.id, title: "Half" })).rejects.toMatchObject({
      code: "PRECONDITION_FAILED",
      message: expect.stringContaining(
        "“Retired robot” is for the robot “no-such-robot”, whose plugin is not installed",
      ),
    });
    expect(await owner.studies.mine()).toHaveLength(before);
  });
});
