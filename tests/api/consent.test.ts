// A trial needs a participant with recorded consent, unless the study turns
// that check off; consent changes are logged.
import type { TRPCError } from "@trpc/server";
import { afterAll, describe, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

async function setUp() {
  const study = await f.newStudy();
  const experiment = await owner.experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
  await owner.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "Only", actions: [{ type: "wave" }] }],
  });
  const version = await owner.versions.publish({ experimentId: experiment.id });
  const participant = await owner.participants.create({ studyId: study.id, code: "P9" });
  return { study, version, participant };
}

describe("consent gating", () => {
  it("refuses a trial for a participant without recorded consent, and says how to proceed", async () => {
    const { version, participant } = await setUp();
    const error = await f
      .api("wizard")
      .trials.create({ versionId: version.id, participantId: participant.id })
      .catch((e: TRPCError) => e);
    expect(error).toMatchObject({
      code: "PRECONDITION_FAILED",
      message:
        "P9 has no recorded consent (pending). Record their consent first, or turn off the consent check in the study's overview.",
    });
  });

  it("allows it once consent is given, and logs the change", async () => {
    const { study, version, participant } = await setUp();
    await owner.participants.update({ participantId: participant.id, consentStatus: "given", consentDate: new Date() });
    await expect(
      f.api("wizard").trials.create({ versionId: version.id, participantId: participant.id }),
    ).resolves.toMatchObject({ status: "scheduled" });
    await owner.participants.update({ participantId: participant.id, consentStatus: "withdrawn" });
    const log = (await f.api("admin").admin.auditLog({ limit: 50 }))
      .filter((e) => e.studyId === study.id)
      .map((e) => e.action);
    expect(log).toEqual(expect.arrayContaining(["participant.consent.given", "participant.consent.withdrawn"]));
  });

  it("allows it without consent when the owner turns the check off", async () => {
    const { study, version, participant } = await setUp();
    await owner.studies.update({ studyId: study.id, settings: { requireConsent: false } });
    expect((await owner.studies.get({ studyId: study.id })).settings.requireConsent).toBe(false);
    await expect(
      f.api("wizard").trials.create({ versionId: version.id, participantId: participant.id }),
    ).resolves.toMatchObject({ status: "scheduled" });
  });
});
