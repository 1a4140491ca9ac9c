// A version published in an earlier format of the experiment document, as it
// was stored then, still verifies against its hash and still runs: the
// runtime reads it upgraded (core/protocol/versions.ts), a wizard runs it on
// the simulated NAO6 to its end, and its stored value is never rewritten.
import { readFileSync } from "node:fs";
import { eq, sql } from "drizzle-orm";
import { afterAll, expect, it } from "vitest";
import { hashCanonical } from "../../src/core/protocol/canonical";
import { nextUnit } from "../../src/core/trial";
import { experimentVersions, experiments, studies, trials } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { simulatedHosts } from "../support/simulated-hosts";

const nao = firstPartyPlugin("nao6-ros2.json");
// The storyteller as commit 3912942 published it: format version 1, the robot named robotPluginId.
const { hash, snapshot } = JSON.parse(readFileSync("tests/fixtures/documents/storyteller.v1.snapshot.json", "utf8"));

const { db, url, close } = await freshDatabase();
const { sim, hosts, close: closeHosts } = await simulatedHosts(db, url, nao);

afterAll(async () => {
  await closeHosts();
  await close();
});

/** The stored snapshot as PostgreSQL holds it, and whether it still hashes to its version's hash. */
async function stored(versionId: string) {
  const [row] = await db.execute<{ text: string; hash: string }>(
    sql`select snapshot::text as text, hash from experiment_versions where id = ${versionId}`,
  );
  return { text: row!.text, verifies: hashCanonical(JSON.parse(row!.text)) === row!.hash };
}

it("a version of format 1 verifies, runs to its end on the simulated NAO6, and is never rewritten", {
  timeout: 60_000,
}, async () => {
  const [study] = await db.insert(studies).values({ title: "Published before" }).returning();
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId: study!.id, name: snapshot.experiment.name, robotId: "nao6-ros2" })
    .returning();
  // Written as it was then: the column stores what it is given.
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot, hash, robotId: "nao6-ros2" })
    .returning({ id: experimentVersions.id });
  const [trial] = await db
    .insert(trials)
    .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id })
    .returning({ id: trials.id });
  const before = await stored(version!.id);
  expect(before.verifies).toBe(true);

  // Read through the schema, it is today's shape.
  const [read] = await db
    .select({ snapshot: experimentVersions.snapshot })
    .from(experimentVersions)
    .where(eq(experimentVersions.id, version!.id));
  expect(read!.snapshot.experiment.robotId).toBe("nao6-ros2");

  const host = (await hosts.get(trial!.id))!;
  expect((await host.command({ kind: "start" }, null)).ok).toBe(true);
  // The wizard presses on, answering "correct" when asked, until the trial ends.
  for (let press = 0; press < 200 && host.current.status === "in_progress"; press++) {
    const unit = nextUnit(read!.snapshot, host.current);
    const command =
      unit[0]?.type === "record_answer"
        ? { kind: "answer" as const, actionId: unit[0].id, optionId: "correct" }
        : { kind: "next" as const };
    const done = await host.command(command, null);
    if (!done.ok) await new Promise((r) => setTimeout(r, 20));
  }
  expect(host.current.status).toBe("completed");
  expect(host.current.path).toEqual(["introduction", "story", "recall", "response-correct"]);
  const spoken = sim.received.filter((r) => r.message.op === "publish" && r.message.topic === "/speech");
  expect(JSON.stringify(spoken.at(0)?.message)).toContain("Hello. I want to tell you about Kai");

  // Never rewritten: the same stored value, still verifying.
  expect(await stored(version!.id)).toEqual(before);
});
