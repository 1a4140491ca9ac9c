// Who a new trial belongs to: its creator by default, a named wizard, or no
// one yet (`wizardId: null`), in which case whoever starts it claims it (the
// runtime's side is tests/runtime/socket-access.test.ts); and who created it,
// kept apart from its wizard everywhere the trial is shown.
import { strFromU8 } from "fflate";
import { afterAll, describe, expect, it } from "vitest";
import { appendEvents } from "../../src/store/event-store";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { buildFixture, plannedSession, publishedVersion, unzipArchive } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

it("assigns the creator by default, the named wizard when given, and no one for an explicit null", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const versionId = version.id;
  expect(await owner.trials.create({ versionId })).toMatchObject({ wizardId: f.people.owner.id });
  expect(await owner.trials.create({ versionId, wizardId: f.people.wizard.id })).toMatchObject({
    wizardId: f.people.wizard.id,
  });
  expect(await owner.trials.create({ versionId, wizardId: null })).toMatchObject({ wizardId: null });
  await expect(owner.trials.create({ versionId, wizardId: f.people.observer.id })).rejects.toMatchObject({
    code: "BAD_REQUEST",
  });
});

describe("the wizard and the creator, two named fields wherever the trial is shown", () => {
  it("names both on the trial, in the study's list, in the CSV and JSON downloads and in the study archive", async () => {
    const study = await f.newStudy();
    const { version } = await publishedVersion(owner, study.id);
    const participant = await owner.participants.create({
      studyId: study.id,
      code: "P1",
      consentStatus: "given",
      consentDate: new Date(),
    });
    const trial = await owner.trials.create({
      versionId: version.id,
      participantId: participant.id,
      wizardId: f.people.wizard.id,
    });
    const names = { wizardName: f.people.wizard.name, createdByName: f.people.owner.name };
    expect(f.people.wizard.name).not.toBe(f.people.owner.name);
    expect(await owner.trials.get({ trialId: trial.id })).toMatchObject(names);
    expect((await owner.trials.list({ studyId: study.id }))[0]).toMatchObject(names);

    const [header, row] = parseCsv(
      await new Response((await owner.trials.export({ trialId: trial.id, format: "csv" })).body).text(),
    );
    // No events yet: the header alone, so log one to see a row.
    expect(header!.slice(0, 3)).toEqual(["trial_id", "wizard", "created_by"]);
    expect(row).toBeUndefined();
    await appendEvents(db, { id: trial.id, lastSeq: 0, t0: null }, [{ type: "trial.started" }], f.people.wizard.id);
    const csvRows = (body: string) => parseCsv(body).slice(1);
    expect(
      csvRows(
        await new Response((await owner.trials.export({ trialId: trial.id, format: "csv" })).body).text(),
      )[0]!.slice(0, 3),
    ).toEqual([trial.id, f.people.wizard.name, f.people.owner.name]);
    const record = JSON.parse(
      await new Response((await owner.trials.export({ trialId: trial.id, format: "json" })).body).text(),
    );
    expect(record.trial).toMatchObject({ wizardId: f.people.wizard.id, createdBy: f.people.owner.id, ...names });

    const archive = await unzipArchive(await f.routeApi("owner").studies.exportArchive({ studyId: study.id }));
    expect(JSON.parse(strFromU8(archive[`trials/${trial.id}.json`]!)).trial).toMatchObject(names);
    expect(csvRows(strFromU8(archive[`trials/${trial.id}-events.csv`]!))[0]!.slice(1, 3)).toEqual([
      f.people.wizard.name,
      f.people.owner.name,
    ]);
  });

  it("credits a session's trial to the wizard who starts it and to the researcher who planned it", async () => {
    const study = await f.newStudy();
    const { experiment } = await publishedVersion(owner, study.id);
    const researcher = f.api("researcher");
    const { session } = await plannedSession(researcher, study.id, experiment.id, "P2", f.people.wizard.id);
    const { trialId } = await f.api("wizard").sessions.start({ sessionId: session.id });
    expect(await owner.trials.get({ trialId })).toMatchObject({
      wizardId: f.people.wizard.id,
      wizardName: f.people.wizard.name,
      createdBy: f.people.researcher.id,
      createdByName: f.people.researcher.name,
    });
  });
});
