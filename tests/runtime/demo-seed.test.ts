// A newcomer's first trial: the demo seed publishes the Interactive
// Storyteller, so the demo wizard starts a trial of it at once, with no
// "Publish this experiment first"; publishing the unchanged draft again is
// that same version 1, not a copy under a new number.
import { sql } from "drizzle-orm";
import { afterAll, expect, it } from "vitest";
import { hashCanonical } from "../../src/core/protocol/canonical";
import { seedDemo } from "../../src/server/seed/demo";
import { buildFixture, demoPerson } from "../api/fixture";
import { freshDatabase } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { simulatedHosts } from "../support/simulated-hosts";

const nao = firstPartyPlugin("nao6-ros2.json");
const { db, url, close } = await freshDatabase();
await seedDemo(db);
const f = await buildFixture(db);
const { hosts, close: closeHosts } = await simulatedHosts(db, url, nao);

afterAll(async () => {
  await closeHosts();
  await close();
});

it("seeds the Storyteller published as version 1, whose stored snapshot hashes to its hash", async () => {
  const researcher = f.apiAs(await demoPerson(db, "researcher@demo.hristudio"));
  const [study] = await researcher.studies.mine();
  const [experiment] = await researcher.experiments.list({ studyId: study!.id });
  const versions = await researcher.versions.list({ experimentId: experiment!.id });
  expect(versions.map((v) => v.version)).toEqual([1]);
  const [row] = await db.execute<{ text: string; hash: string }>(
    sql`select snapshot::text as text, hash from experiment_versions where id = ${versions[0]!.id}`,
  );
  expect(hashCanonical(JSON.parse(row!.text))).toBe(row!.hash);
  expect(row!.hash).toBe(versions[0]!.hash);

  // The draft is unchanged since: publishing it again is version 1 itself.
  const again = await researcher.versions.publish({ experimentId: experiment!.id });
  expect([again.id, again.version, again.hash]).toEqual([versions[0]!.id, 1, versions[0]!.hash]);
  expect((await researcher.versions.list({ experimentId: experiment!.id })).map((v) => v.version)).toEqual([1]);
});

it("lets the demo wizard start a trial of the seeded version at once", { timeout: 30_000 }, async () => {
  const wizard = f.apiAs(await demoPerson(db, "wizard@demo.hristudio"));
  const [study] = await wizard.studies.mine();
  const [experiment] = await wizard.experiments.list({ studyId: study!.id });
  const [version] = await wizard.versions.list({ experimentId: experiment!.id });
  const [participant] = await wizard.participants.list({ studyId: study!.id });
  const trial = await wizard.trials.create({ versionId: version!.id, participantId: participant!.id });
  const host = (await hosts.get(trial.id))!;
  expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
  expect(host.current.status).toBe("in_progress");
});
