// Conditions and their assignment: made on the server, balanced, and
// reproducible from the seed and position it records.
import type { TRPCError } from "@trpc/server";
import { afterAll, describe, expect, it } from "vitest";
import { assign } from "../../src/core/studies/assignment";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

async function studyWithConditions(
  strategy: "fixed" | "random" | "balanced" | "counterbalanced",
  perCondition = 1,
) {
  const study = await f.newStudy();
  const nao = await owner.experiments.create({
    studyId: study.id,
    name: "Storyteller on NAO",
    robotId: "nao6-ros2",
  });
  const bot = await owner.experiments.create({
    studyId: study.id,
    name: "Storyteller on TurtleBot",
    robotId: "turtlebot3-burger",
  });
  const gestures = await owner.conditions.create({
    studyId: study.id,
    name: "NAO with gestures",
    experimentId: nao.id,
  });
  const voice = await owner.conditions.create({
    studyId: study.id,
    name: "TurtleBot voice only",
    experimentId: bot.id,
  });
  await owner.studies.update({ studyId: study.id, settings: { assignment: { strategy, perCondition } } });
  const participant = (code: string) =>
    owner.participants.create({ studyId: study.id, code, consentStatus: "given", consentDate: new Date() });
  return { study, gestures, voice, participant };
}

describe("condition assignment", () => {
  it("balances a blocked randomisation and records seed and position for an audit", async () => {
    const { study, gestures, voice, participant } = await studyWithConditions("balanced", 2);
    const seed = (await owner.studies.get({ studyId: study.id })).settings.assignment.seed!;
    expect(seed).toMatch(/^[0-9a-f]{24}$/);
    const assigned: Array<Awaited<ReturnType<typeof owner.conditions.assign>>> = [];
    for (let i = 1; i <= 8; i++)
      assigned.push(await owner.conditions.assign({ participantId: (await participant(`P${i}`)).id }));
    const names = { [gestures.id]: gestures.name, [voice.id]: voice.name };
    const counts = (upTo: number) => assigned.slice(0, upTo).filter((p) => p.conditionId === gestures.id).length;
    expect(counts(8)).toBe(4);
    expect(Math.abs(counts(4) - 2)).toBe(0);
    // Anyone with the seed reproduces every assignment.
    for (const p of assigned) {
      const record = p.assignment as { seed: string; position: number };
      expect(
        assign({ kind: "balanced", perCondition: 2 }, [gestures.name, voice.name], record.seed, record.position),
      ).toEqual({ condition: names[p.conditionId!] });
    }
    const listed = await owner.conditions.list({ studyId: study.id });
    expect(listed.map((c) => [c.name, c.participantCount])).toEqual([
      ["NAO with gestures", 4],
      ["TurtleBot voice only", 4],
    ]);
  });

  it("gives each participant an order of all conditions when counterbalanced", async () => {
    const { gestures, voice, participant } = await studyWithConditions("counterbalanced");
    const first = await owner.conditions.assign({ participantId: (await participant("W1")).id });
    const second = await owner.conditions.assign({ participantId: (await participant("W2")).id });
    expect([first.conditionOrder, second.conditionOrder]).toEqual([
      [gestures.id, voice.id],
      [voice.id, gestures.id],
    ]);
  });

  it("needs the researcher's choice when fixed, and never redraws", async () => {
    const { gestures, participant } = await studyWithConditions("fixed");
    const p = await participant("F1");
    await expect(owner.conditions.assign({ participantId: p.id })).rejects.toThrow(
      "Choose one of the conditions: NAO with gestures, TurtleBot voice only.",
    );
    expect((await owner.conditions.assign({ participantId: p.id, conditionId: gestures.id })).conditionId).toBe(
      gestures.id,
    );
    const again = await owner.conditions
      .assign({ participantId: p.id, conditionId: gestures.id })
      .catch((e: TRPCError) => e);
    expect(again).toMatchObject({
      code: "CONFLICT",
      message: "F1 is already assigned; assignments are never redrawn.",
    });
  });

  it("balances each stratum of a demographic question on its own, and says which it used", async () => {
    const { study, gestures, participant } = await studyWithConditions("fixed");
    const where = await owner.studies
      .update({ studyId: study.id, settings: { assignment: { strategy: "stratified", stratifyBy: "experience" } } })
      .catch((e: TRPCError) => e);
    expect(where).toMatchObject({
      code: "BAD_REQUEST",
      message: 'Assignment: "experience" is not a demographic question of this study',
    });
    await owner.studies.update({
      studyId: study.id,
      settings: {
        demographics: [
          { key: "experience", label: "Programming experience", type: "choice", options: ["none", "some"] },
        ],
        assignment: { strategy: "stratified", stratifyBy: "experience", perCondition: 1 },
      },
    });
    // Six novices first, then six with experience: a study-wide block would mix them, strata keep each even.
    const codes = [...Array.from({ length: 6 }, (_, i) => `N${i}`), ...Array.from({ length: 6 }, (_, i) => `E${i}`)];
    const assigned = [];
    for (const code of codes) {
      const p = await participant(code);
      await owner.participants.update({
        participantId: p.id,
        demographics: { experience: code.startsWith("N") ? "none" : "some" },
      });
      assigned.push(await owner.conditions.assign({ participantId: p.id }));
    }
    for (const group of ["none", "some"]) {
      const inGroup = assigned.filter((p) => (p.assignment as { stratum: string }).stratum === group);
      expect(inGroup).toHaveLength(6);
      expect(inGroup.filter((p) => p.conditionId === gestures.id)).toHaveLength(3);
      expect(inGroup.map((p) => (p.assignment as { position: number }).position)).toEqual([0, 1, 2, 3, 4, 5]);
    }
    expect(assigned[0]!.assignment).toMatchObject({ strategy: "stratified", stratifyBy: "experience" });
    const listed = await owner.participants.list({ studyId: study.id });
    expect(listed.find((p) => p.code === "E0")?.stratum).toBe("some");
    // The question cannot go while assignment stratifies by it.
    await expect(owner.studies.update({ studyId: study.id, settings: { demographics: [] } })).rejects.toThrow(
      '"experience" is not a demographic question of this study',
    );
  });
});
