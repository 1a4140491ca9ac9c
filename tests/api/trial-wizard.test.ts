// Who a new trial belongs to: its creator by default, a named wizard, or no
// one yet (`wizardId: null`), in which case the first wizard to start it claims it.
import { afterAll, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

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
