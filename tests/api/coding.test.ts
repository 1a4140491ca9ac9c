// Coding schemes through the API: made from a template, checked and versioned
// like questionnaires; codes added afterwards in one's own tier only.
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { strFromU8 } from "fflate";
import { CODE_COLUMNS } from "../../src/core/coding/export";
import { schemeTemplate } from "../../src/core/coding/templates";
import { codingSchemeVersions } from "../../src/store/schema";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion, unzipArchive } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
afterAll(close);

const owner = f.api("owner");
const study = await f.newStudy();
const { version } = await publishedVersion(owner, study.id);
const trial = await owner.trials.create({ versionId: version.id });

describe("coding schemes", () => {
  it("starts from a template, refuses a broken scheme with every problem named, and publishes numbered versions", async () => {
    const { id } = await owner.coding.createScheme({ studyId: study.id, template: "wizard-interventions" });
    expect((await f.api("observer").coding.scheme({ codingSchemeId: id })).draft).toEqual(
      schemeTemplate("wizard-interventions"),
    );
    const broken = schemeTemplate("wizard-interventions");
    broken.sets[0]!.codes[1]!.key = "t";
    broken.sets[0]!.codes[2]!.colour = "orange";
    await expect(owner.coding.saveScheme({ codingSchemeId: id, definition: broken })).rejects.toMatchObject({
      code: "BAD_REQUEST",
      message:
        'Please correct: definition.sets.0.codes.2.colour: must be a colour like #3b82f6; definition.sets.0.codes.1.key: "t" is already the key of Technical',
    });
    const first = await owner.coding.publishScheme({ codingSchemeId: id });
    const renamed = { ...schemeTemplate("wizard-interventions"), name: "Interventions (v2)" };
    await owner.coding.saveScheme({ codingSchemeId: id, definition: renamed });
    const second = await owner.coding.publishScheme({ codingSchemeId: id });
    expect([first.version, second.version]).toEqual([1, 2]);
    expect(first.hash).not.toBe(second.hash);
    expect(await f.api("observer").coding.schemes({ studyId: study.id })).toContainEqual({
      id,
      name: "Interventions (v2)",
      latestVersion: 2,
      latestVersionId: second.id,
    });
    // Observers code with the latest published version.
    const forTrial = await f.api("observer").coding.forTrial({ trialId: trial.id });
    expect(forTrial.schemes.find((s) => s.schemeId === id)).toMatchObject({ versionId: second.id, version: 2 });
  });

  it("keeps each observer's codes their own: added, moved and deleted by them alone", async () => {
    const { id } = await owner.coding.createScheme({ studyId: study.id, template: "participant-engagement" });
    const { id: schemeVersionId } = await owner.coding.publishScheme({ codingSchemeId: id });
    const observer = f.api("observer");
    const gaze = await observer.coding.addCode({
      trialId: trial.id,
      schemeVersionId,
      setId: "gaze",
      codeId: "robot",
      startMs: 1000,
      endMs: 4000,
    });
    const smile = await f.api("researcher").coding.addCode({
      trialId: trial.id,
      schemeVersionId,
      setId: "expression",
      codeId: "smile",
      startMs: 2500,
      modifiers: ["laugh"],
    });
    await expect(
      observer.coding.addCode({ trialId: trial.id, schemeVersionId, setId: "gaze", codeId: "robot", startMs: 5 }),
    ).rejects.toMatchObject({ message: "Please correct: endMs: a state must end at or after its start" });
    await expect(
      observer.coding.addCode({ trialId: trial.id, schemeVersionId, setId: "gaze", codeId: "blink", startMs: 5 }),
    ).rejects.toMatchObject({ message: "“Participant engagement” has no code gaze/blink." });
    await expect(
      observer.coding.addCode({
        trialId: trial.id,
        schemeVersionId,
        setId: "expression",
        codeId: "smile",
        startMs: 5,
        modifiers: ["grin"],
      }),
    ).rejects.toMatchObject({ message: "“Smile” has no modifier “grin”." });
    await expect(observer.coding.deleteCode({ codeEventId: smile.id })).rejects.toMatchObject({
      code: "FORBIDDEN",
      message: "This code is another observer's: only they may change it.",
    });
    await expect(owner.coding.moveCode({ codeEventId: gaze.id, startMs: 0, endMs: 1 })).rejects.toMatchObject({
      code: "FORBIDDEN",
    });
    expect(await observer.coding.moveCode({ codeEventId: gaze.id, startMs: 1200, endMs: 4200 })).toMatchObject({
      startMs: 1200,
      endMs: 4200,
    });
    const tiers = (await owner.coding.codes({ trialId: trial.id })).filter((c) => c.versionId === schemeVersionId);
    expect(tiers.map((c) => [c.observerName, c.codeId, c.startMs, c.endMs, c.modifiers])).toEqual([
      ["observer", "robot", 1200, 4200, []],
      ["researcher", "smile", 2500, null, ["laugh"]],
    ]);
    await f.api("researcher").coding.deleteCode({ codeEventId: smile.id });
    expect((await owner.coding.codes({ trialId: trial.id })).map((c) => c.id)).not.toContain(smile.id);
  });

  it("computes Cohen's kappa per set between the two observers, per trial and pooled", async () => {
    const { id } = await owner.coding.createScheme({ studyId: study.id, template: "participant-engagement" });
    const { id: schemeVersionId } = await owner.coding.publishScheme({ codingSchemeId: id });
    const gaze = async (who: "observer" | "researcher", codeId: string, startMs: number, endMs: number) =>
      f.api(who).coding.addCode({ trialId: trial.id, schemeVersionId, setId: "gaze", codeId, startMs, endMs });
    await gaze("observer", "robot", 0, 2000);
    await gaze("observer", "away", 2000, 4000);
    await gaze("researcher", "robot", 0, 3000);
    await gaze("researcher", "away", 3000, 4000);
    const result = await f.api("observer").coding.agreement({ schemeVersionId });
    expect(result.observers.map((o) => o.name).sort()).toEqual(["observer", "researcher"]);
    const [pair] = result.pairs;
    const gazeAgreement = pair!.pooled.find((s) => s.setId === "gaze")!;
    const flip =
      pair!.a === f.people.observer.id
        ? (t: number[][]) => t
        : (t: number[][]) => t[0]!.map((_, j) => t.map((r) => r[j]!));
    expect(flip(gazeAgreement.table.counts)).toEqual([
      [2, 0, 0, 0],
      [0, 0, 0, 0],
      [1, 0, 1, 0],
      [0, 0, 0, 0],
    ]);
    expect(gazeAgreement.table.categories).toEqual(["robot", "task", "away", "(none)"]);
    // The figure is shown in the scheme's words: each set's and code's name beside its id.
    expect(result.sets.find((s) => s.id === "gaze")).toEqual({
      id: "gaze",
      name: "Gaze",
      codes: [
        { id: "robot", name: "At the robot" },
        { id: "task", name: "At the task" },
        { id: "away", name: "Away" },
      ],
    });
    expect(gazeAgreement.kappa).toBeCloseTo(0.5, 6);
    // Nobody coded an expression: no slices differ, but chance agreement is certain, so kappa is undefined.
    expect(pair!.pooled.find((s) => s.setId === "expression")!.kappa).toBeNull();
    expect(pair!.trials.map((t) => t.trialId)).toEqual([trial.id]);
  });

  it("puts every code in the trial's JSON and codes CSV, and the study zip's codes.csv", async () => {
    const participant = await owner.participants.create({
      studyId: study.id,
      code: "P-codes",
      consentStatus: "given",
      consentDate: new Date(),
    });
    const coded = await owner.trials.create({ versionId: version.id, participantId: participant.id });
    const { id } = await owner.coding.createScheme({ studyId: study.id, template: "participant-engagement" });
    const { id: schemeVersionId } = await owner.coding.publishScheme({ codingSchemeId: id });
    await f.api("observer").coding.addCode({
      trialId: coded.id,
      schemeVersionId,
      setId: "expression",
      codeId: "hesitation",
      startMs: 800,
      modifiers: ["verbal", "gesture"],
    });
    await f
      .api("researcher")
      .coding.addCode({ trialId: coded.id, schemeVersionId, setId: "gaze", codeId: "away", startMs: 0, endMs: 900 });
    const rows = [
      [coded.id, "researcher", "Participant engagement", "1", "Gaze", "Away", "state", "0", "900", ""],
      [
        coded.id,
        "observer",
        "Participant engagement",
        "1",
        "Expression",
        "Hesitation",
        "point",
        "800",
        "",
        "verbal; gesture",
      ],
    ];
    const csv = await owner.trials.export({ trialId: coded.id, format: "codes" });
    expect(csv.filename).toBe(`trial-${coded.id}-codes.csv`);
    expect(parseCsv(csv.body as string)).toEqual([[...CODE_COLUMNS], ...rows]);
    const record = JSON.parse(
      await new Response((await owner.trials.export({ trialId: coded.id, format: "json" })).body).text(),
    );
    expect(record.schemaVersion).toBe(3);
    expect(record.codes).toEqual([
      expect.objectContaining({ observer: "researcher", set: "Gaze", code: "Away", start_ms: 0, end_ms: 900 }),
      expect.objectContaining({ observer: "observer", code: "Hesitation", end_ms: null, modifiers: "verbal; gesture" }),
    ]);
    const archive = await unzipArchive(await f.routeApi("owner").studies.exportArchive({ studyId: study.id }));
    expect(parseCsv(strFromU8(archive["codes.csv"]!))).toEqual([[...CODE_COLUMNS], ...rows]);
  });

  it("names a scheme as it is called now in the codes CSV, and counts agreement in the window asked for", async () => {
    const coded = await owner.trials.create({ versionId: version.id });
    const { id } = await owner.coding.createScheme({ studyId: study.id });
    const named = { ...schemeTemplate("participant-engagement"), name: "Gaze coding (Lab B)" };
    await owner.coding.saveScheme({ codingSchemeId: id, definition: { ...named, name: "New coding scheme" } });
    const { id: schemeVersionId } = await owner.coding.publishScheme({ codingSchemeId: id });
    const gaze = async (who: "observer" | "researcher", codeId: string, startMs: number, endMs: number) =>
      f.api(who).coding.addCode({ trialId: coded.id, schemeVersionId, setId: "gaze", codeId, startMs, endMs });
    await gaze("observer", "robot", 0, 2000);
    await gaze("observer", "away", 2000, 4000);
    await gaze("researcher", "away", 2000, 4000);
    // Renamed after the codes were made: the codes CSV says the name the team gave it.
    await owner.coding.saveScheme({ codingSchemeId: id, definition: named });
    const csv = parseCsv((await owner.trials.export({ trialId: coded.id, format: "codes" })).body as string);
    expect(new Set(csv.slice(1).map((r) => r[CODE_COLUMNS.indexOf("scheme")]))).toEqual(
      new Set(["Gaze coding (Lab B)"]),
    );
    const observed = async (window: "trial" | "bothCoding") => {
      const result = await f.api("observer").coding.agreement({ schemeVersionId, window });
      expect(result.counted.window).toBe(window);
      const set = result.pairs[0]!.trials.find((t) => t.trialId === coded.id)!.sets.find((s) => s.setId === "gaze")!;
      return [set.n, set.observed];
    };
    // The first two seconds only one observer coded: they disagree over the trial, and are left out from when both coded.
    expect(await observed("trial")).toEqual([4, 0.5]);
    expect(await observed("bothCoding")).toEqual([2, 1]);

    // The window kept with the scheme is what agreement counts when none is asked for, and the version stays as it was.
    const asked = () => f.api("observer").coding.agreement({ schemeVersionId });
    expect((await asked()).counted).toEqual({ sliceMs: 1000, window: "trial", stepIds: [] });
    const counted = { sliceMs: 1000, window: "bothCoding" as const, stepIds: [] };
    await expect(f.api("observer").coding.keepCounted({ codingSchemeId: id, counted })).rejects.toMatchObject({
      code: "FORBIDDEN",
    });
    expect(await owner.coding.keepCounted({ codingSchemeId: id, counted })).toEqual(counted);
    const kept = await asked();
    expect([kept.counted, kept.kept]).toEqual([counted, counted]);
    expect(kept.pairs[0]!.trials.find((t) => t.trialId === coded.id)!.sets.find((s) => s.setId === "gaze")!.n).toBe(2);
    expect((await owner.coding.scheme({ codingSchemeId: id })).draft.counted).toEqual(counted);
    // A version freezes what coders code with; how agreement is counted is not part of it.
    const republished = await owner.coding.publishScheme({ codingSchemeId: id });
    const [frozen] = await db.select().from(codingSchemeVersions).where(eq(codingSchemeVersions.id, republished.id));
    expect(Object.keys(frozen!.definition as object)).not.toContain("counted");
    await expect(
      f.api("observer").coding.agreement({ schemeVersionId, window: "idle" as "trial" }),
    ).rejects.toMatchObject({
      code: "BAD_REQUEST",
      message: expect.stringContaining("must be one of trial, bothCoding, steps"),
    });
  });

  it("goes with its study: a study with published schemes and codes is deleted whole", async () => {
    const doomed = await f.newStudy("Doomed");
    const { version: v } = await publishedVersion(owner, doomed.id);
    const t = await owner.trials.create({ versionId: v.id });
    const { id } = await owner.coding.createScheme({ studyId: doomed.id, template: "wizard-interventions" });
    const { id: schemeVersionId } = await owner.coding.publishScheme({ codingSchemeId: id });
    await owner.coding.addCode({ trialId: t.id, schemeVersionId, setId: "intervention", codeId: "hint", startMs: 1 });
    await owner.studies.delete({ studyId: doomed.id, confirmTitle: "Doomed" });
    await expect(owner.coding.scheme({ codingSchemeId: id })).rejects.toMatchObject({ code: "NOT_FOUND" });
  });
});
