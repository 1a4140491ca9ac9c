// The dashboard's "live now" list: running trials of the caller's own studies
// only, each blinded by the caller's role in that study.
import { afterAll, expect, it } from "vitest";
import { eq } from "drizzle-orm";
import { BLINDED_NAME } from "../../src/core/studies/blinding";
import { appendEvents } from "../../src/store/event-store";
import { studies, studyMembers } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

const running = async (trialId: string, wizardId: string) =>
  appendEvents(db, { id: trialId, lastSeq: 0, t0: null }, [{ type: "trial.started" }], wizardId);

it("lists the trials running now in my studies, one click from watching, and no others", async () => {
  const study = await f.newStudy("Live study");
  const { version } = await publishedVersion(owner, study.id);
  const live = await owner.trials.create({ versionId: version.id, wizardId: f.people.wizard.id });
  const scheduled = await owner.trials.create({ versionId: version.id });
  await running(live.id, f.people.wizard.id);
  // Another study, the outsider's own, with a trial running too.
  const elsewhere = await f.api("outsider").studies.create({ title: "Elsewhere" });
  await db.update(studies).set({ status: "active" }).where(eq(studies.id, elsewhere.id));
  const other = await publishedVersion(f.api("outsider"), elsewhere.id);
  const otherTrial = await f.api("outsider").trials.create({ versionId: other.version.id });
  await running(otherTrial.id, f.people.outsider.id);

  for (const who of ["owner", "researcher", "wizard", "observer"] as const) {
    const list = await f.api(who).trials.liveNow();
    expect(list.map((t) => t.trialId)).toEqual([live.id]);
    expect(list[0]).toMatchObject({
      studyId: study.id,
      studyTitle: "Live study",
      experimentName: "E",
      status: "in_progress",
      wizardName: f.people.wizard.name,
      myRole: who,
    });
  }
  expect((await f.api("outsider").trials.liveNow()).map((t) => t.trialId)).toEqual([otherTrial.id]);
  expect(await f.api("admin").trials.liveNow()).toEqual([]);
  expect((await owner.trials.liveNow()).map((t) => t.trialId)).not.toContain(scheduled.id);

  // Once it has ended, it is no longer live.
  await appendEvents(
    db,
    { id: live.id, lastSeq: 1, t0: new Date() },
    [{ type: "trial.completed" }],
    f.people.wizard.id,
  );
  expect(await f.api("observer").trials.liveNow()).toEqual([]);
});

it("hides the experiment's name from a wizard blinded to conditions, and drops a removed member at once", async () => {
  const study = await f.newStudy("Blind study");
  await owner.studies.update({ studyId: study.id, settings: { blinding: { conditionsFromWizards: true } } });
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id, wizardId: f.people.wizard.id });
  await running(trial.id, f.people.wizard.id);
  const forWizard = (await f.api("wizard").trials.liveNow()).find((t) => t.trialId === trial.id);
  expect(forWizard?.experimentName).toBe(BLINDED_NAME);
  expect(JSON.stringify(forWizard)).not.toContain(version.id);
  const forResearcher = (await f.api("researcher").trials.liveNow()).find((t) => t.trialId === trial.id);
  expect(forResearcher?.experimentName).toBe("E");
  await db.delete(studyMembers).where(eq(studyMembers.userId, f.people.observer.id));
  expect(await f.api("observer").trials.liveNow()).toEqual([]);
});
