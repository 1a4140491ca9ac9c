// Annotations made afterwards on the analysis page: any member may add one;
// its author may edit it, and so may the study's owner and researchers.
import { afterAll, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
afterAll(close);

it("lets the author and the researchers edit a annotation, and nobody else", async () => {
  const owner = f.api("owner");
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  const { id } = await f
    .api("observer")
    .trials.annotate({ trialId: trial.id, relMs: 61_500, label: "Looks away", note: "" });
  await expect(f.api("wizard").trials.editAnnotation({ annotationId: id, label: "x", note: "" })).rejects.toMatchObject(
    { code: "FORBIDDEN", message: expect.stringMatching(/^Only the person who wrote this annotation/) },
  );
  await f.api("observer").trials.editAnnotation({ annotationId: id, label: "Looks away from the robot", note: "" });
  await f
    .api("researcher")
    .trials.editAnnotation({ annotationId: id, label: "Looks away from the robot", note: "during the story" });
  expect(await owner.trials.annotations({ trialId: trial.id })).toMatchObject([
    { id, relMs: 61_500, label: "Looks away from the robot", note: "during the story", authorName: expect.any(String) },
  ]);
});
