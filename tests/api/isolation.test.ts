// One lab server, two studies, nothing crossing. Generated from the router:
// for every procedure and every kind of caller in study A, the input that
// works in A (from the access matrix) is sent again (b) with every id swapped
// for study B's row of the same kind, and (c) with one id at a time swapped,
// and with each id key it does not use added as B's (and, the other way, B's
// ids with each unused key added as A's: the hole this test was written for).
// Every one must be
// refused, and study B's rows must come out of it byte for byte unchanged.
import { TRPCError } from "@trpc/server";
import { afterAll, describe, expect, it } from "vitest";
import { isStudyOperation, type Operation } from "../../src/core/access/policy";
import { ACROSS_STUDIES, REFERENCES, type ReferenceKey } from "../../src/server/access/resources";
import { appRouter } from "../../src/server/api/root";
import type { Meta } from "../../src/server/api/trpc";
import { freshDatabase } from "../support/db";
import { codingRows } from "../support/coding";
import { studyFingerprint } from "../support/study-rows";
import { buildFixture, CALLERS, newPerson, type Caller } from "./fixture";
import { baseData, freshAudio, MATRIX } from "./matrix";

type Key = ReferenceKey | keyof typeof ACROSS_STUDIES;

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const a = await baseData(f);
afterAll(close);

/** Study B: owned by someone in no role of study A, with a row of every kind. */
async function victimStudy() {
  const victim = await newPerson(db, "victim");
  const api = f.apiAs(victim);
  const study = await api.studies.create({ title: "Victim study" });
  await api.studies.update({ studyId: study.id, status: "active" });
  const experiment = await api.experiments.create({
    studyId: study.id,
    name: "Secret protocol",
    robotId: "nao6-ros2",
  });
  await api.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "Secret step", actions: [{ type: "say", parameters: { text: "secret" } }] }],
  });
  const version = await api.versions.publish({ experimentId: experiment.id });
  const participant = await api.participants.create({
    studyId: study.id,
    code: "V1",
    consentStatus: "given",
    consentDate: new Date(),
  });
  const condition = await api.conditions.create({
    studyId: study.id,
    name: "Secret condition",
    experimentId: experiment.id,
  });
  await api.conditions.assign({ participantId: participant.id, conditionId: condition.id });
  const session = await api.sessions.schedule({
    participantId: participant.id,
    plannedAt: new Date(),
    wizardId: victim.id,
  });
  const trial = await api.trials.create({ versionId: version.id, participantId: participant.id });
  const annotation = await api.trials.annotate({ trialId: trial.id, relMs: 5, label: "Secret moment" });
  const { recordingId } = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
  const questionnaire = await api.questionnaires.create({ studyId: study.id, instrument: "sus" });
  await api.questionnaires.publish({ questionnaireId: questionnaire.id });
  await api.questionnaires.createLink({
    questionnaireId: questionnaire.id,
    participantId: participant.id,
    trialId: trial.id,
  });
  const ids: Record<Key, string | string[]> = {
    studyId: study.id,
    intoStudyId: study.id,
    experimentId: experiment.id,
    versionId: version.id,
    participantId: participant.id,
    trialId: trial.id,
    conditionId: condition.id,
    recordingId,
    sessionId: session.id,
    annotationId: annotation.id,
    questionnaireId: questionnaire.id,
    audioFileId: (await freshAudio(f, study.id, victim.id)).audioFileId,
    ...(await codingRows(api, study.id, trial.id)),
    wizardId: victim.id,
    userId: victim.id,
  };
  return { id: study.id, ids };
}

const b = await victimStudy();

/** Study A's row of every kind, for smuggling the other way: B's row named, A's id beside it. */
async function ownIds(): Promise<Record<Key, string | string[]>> {
  const owner = f.api("owner");
  const session = await owner.sessions.schedule({
    participantId: (
      await owner.conditions.assign({
        participantId: (
          await owner.participants.create({
            studyId: a.study.id,
            code: "A-S",
            consentStatus: "given",
            consentDate: new Date(),
          })
        ).id,
        conditionId: a.condition.id,
      })
    ).id,
    plannedAt: new Date(),
    wizardId: f.people.wizard.id,
  });
  const annotation = await owner.trials.annotate({ trialId: a.trial.id, relMs: 1, label: "A moment" });
  const { recordingId } = await owner.recordings.start({ trialId: a.trial.id, kind: "video", mimeType: "video/mp4" });
  const questionnaire = await owner.questionnaires.create({ studyId: a.study.id, instrument: "sus" });
  return {
    studyId: a.study.id,
    intoStudyId: a.study.id,
    experimentId: a.experiment.id,
    versionId: a.version.id,
    participantId: a.participant.id,
    trialId: a.trial.id,
    conditionId: a.condition.id,
    recordingId,
    sessionId: session.id,
    annotationId: annotation.id,
    questionnaireId: questionnaire.id,
    audioFileId: (await freshAudio(f, a.study.id, f.people.owner.id)).audioFileId,
    ...(await codingRows(owner, a.study.id, a.trial.id)),
    wizardId: f.people.owner.id,
    userId: f.people.owner.id,
  };
}
const aIds = await ownIds();

const before = await studyFingerprint(db, b.id);

interface ProcedureDef {
  _def: { meta?: Meta; inputs: Array<{ shape?: Record<string, unknown> }> };
}
const procedures = Object.entries(appRouter._def.procedures as unknown as Record<string, ProcedureDef>);
const opOf = (path: string) => procedures.find(([p]) => p === path)![1]._def.meta?.op as Operation | "public";
const isStudyProcedure = (path: string) => {
  const op = opOf(path);
  return op !== "public" && isStudyOperation(op);
};
const KEYS = Object.keys(REFERENCES) as ReferenceKey[];
/**
 * Keys naming a row of another study on purpose (where a copy goes): swapped
 * for B's like every id where a procedure takes one. Never added as extras:
 * a procedure that takes none drops them unread.
 */
const ACROSS = Object.keys(ACROSS_STUDIES) as Array<keyof typeof ACROSS_STUDIES>;
const ALL_KEYS: Key[] = [...KEYS, ...ACROSS];

/** A copy of the input with every value under `keys` (at any depth) replaced by study B's row of that kind. */
function swapped(input: unknown, keys: ReadonlySet<string>): unknown {
  if (Array.isArray(input)) return input.map((v) => swapped(v, keys));
  if (input === null || typeof input !== "object" || input instanceof Date) return input;
  return Object.fromEntries(
    Object.entries(input).map(([k, v]) => [
      k,
      keys.has(k) && v !== null && v !== undefined ? b.ids[k as Key] : swapped(v, keys),
    ]),
  );
}

/** The reference keys an input carries, at any depth. */
function keysIn(input: unknown, found = new Set<Key>()): Set<Key> {
  if (input === null || typeof input !== "object" || input instanceof Date) return found;
  for (const [k, v] of Object.entries(input)) {
    if ((ALL_KEYS as string[]).includes(k) && v !== null && v !== undefined) found.add(k as Key);
    keysIn(v, found);
  }
  return found;
}

/** The attacks on one procedure: everything B's, each id alone B's, and each key it does not use smuggled in as B's. */
function variants(input: unknown): Array<[string, unknown]> {
  const own = keysIn(input);
  const base = input && typeof input === "object" ? (input as Record<string, unknown>) : {};
  const allB = swapped(input, new Set(ALL_KEYS)) as Record<string, unknown>;
  return [
    ["every id of study B", allB],
    ...KEYS.filter((k) => !own.has(k)).map((k): [string, unknown] => [
      `every id of study B and an extra ${k} of study A`,
      { ...allB, [k]: aIds[k] },
    ]),
    ...[...own].map((k): [string, unknown] => [`${k} of study B, the rest of A`, swapped(input, new Set([k]))]),
    ...KEYS.filter((k) => !own.has(k)).map((k): [string, unknown] => [
      `an extra ${k} of study B`,
      { ...base, [k]: b.ids[k] },
    ]),
  ];
}

async function call(caller: Caller, path: string, input: unknown) {
  // As the download routes call: a file procedure answers as it would be downloaded.
  let target: unknown = f.routeApi(caller);
  for (const part of path.split(".")) target = (target as Record<string, unknown>)[part];
  return (target as (i: unknown) => Promise<unknown>)(input).then(
    (result) => ({ ok: true as const, result }),
    (error: unknown) => ({ ok: false as const, error }),
  );
}

describe("study isolation", () => {
  it("knows every procedure", () => {
    expect(procedures.length).toBeGreaterThan(70);
  });

  // Procedures outside any study (accounts, plugins, administration) must carry no study's ids.
  it.each(procedures.filter(([path]) => !isStudyProcedure(path)).map(([path]) => [path]))(
    "%s names no row of a study",
    (path) => {
      const shape = procedures.find(([p]) => p === path)![1]._def.inputs.flatMap((i) => Object.keys(i.shape ?? {}));
      expect(shape.filter((k) => (KEYS as string[]).includes(k) && REFERENCES[k as ReferenceKey] !== "member")).toEqual(
        [],
      );
    },
  );

  const cases = procedures
    .filter(([path]) => isStudyProcedure(path))
    .flatMap(([path]) => CALLERS.map((caller) => [path, caller] as const));

  it.each(cases)("%s by %s: refused with any id of study B", async (path, caller) => {
    const own = MATRIX[path]
      ? await MATRIX[path][1](f, a, caller)
      : { [`${procedures.find(([p]) => p === path)![1]._def.meta!.resource}Id`]: "x" };
    for (const [attack, input] of variants(own)) {
      const outcome = await call(caller, path, input);
      const refusal = outcome.ok ? null : outcome.error instanceof TRPCError ? outcome.error : null;
      expect(
        refusal,
        `${path} by ${caller} with ${attack} was ${outcome.ok ? "allowed" : `an unexpected error: ${String(outcome.error)}`}`,
      ).not.toBeNull();
      expect(["UNAUTHORIZED", "NOT_FOUND", "FORBIDDEN", "BAD_REQUEST"], `${attack}: ${refusal!.message}`).toContain(
        refusal!.code,
      );
    }
  });

  it("left every row of study B as it was", async () => {
    expect(await studyFingerprint(db, b.id)).toBe(before);
  });
});
