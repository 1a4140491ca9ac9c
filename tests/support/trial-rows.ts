// A trial of a study straight in the database, for runtime tests: its
// experiment, that experiment's published version of `snapshot`, and (for a
// run that needs one) a participant; or a rehearsal of a snapshot. The study
// and its wizard are the test's own.
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import type { Database } from "../../src/store/client";
import { oneStep } from "./protocols";
import { experimentVersions, experiments, participants, robotStudies, robots, trials } from "../../src/store/schema";

export async function trialOf(
  db: Database,
  input: { studyId: string; wizardId: string; snapshot: ProtocolSnapshot; withParticipant?: boolean },
): Promise<string> {
  const { studyId, wizardId, snapshot } = input;
  const robotId = snapshot.experiment.robotId;
  const name = snapshot.experiment.name;
  const [experiment] = await db.insert(experiments).values({ studyId, name, robotId }).returning();
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot, hash: `${name}-1`, robotId })
    .returning();
  const participant = input.withParticipant
    ? (await db.insert(participants).values({ studyId, code: "P1" }).returning())[0]
    : undefined;
  const [trial] = await db
    .insert(trials)
    .values({ studyId, experimentId: experiment!.id, versionId: version!.id, participantId: participant?.id, wizardId })
    .returning();
  return trial!.id;
}

/** A rehearsal of `snapshot` in the study, straight in the database: its experiment and the trial, with no version. */
export async function rehearsalOf(db: Database, studyId: string, snapshot: ProtocolSnapshot): Promise<string> {
  const robotId = snapshot.experiment.robotId;
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId, name: snapshot.experiment.name, robotId })
    .returning();
  const [trial] = await db
    .insert(trials)
    .values({ studyId, experimentId: experiment!.id, isRehearsal: true, rehearsalSnapshot: snapshot })
    .returning({ id: trials.id });
  return trial!.id;
}

/** A NAO6 at `rosbridgeUrl` registered for the study (named `robotName`), and a trial of one line ("hi") on it. */
export async function naoTrialOf(
  db: Database,
  input: { studyId: string; wizardId: string; rosbridgeUrl: string; robotName: string },
): Promise<string> {
  const { studyId, wizardId, rosbridgeUrl, robotName } = input;
  const [robot] = await db
    .insert(robots)
    .values({ name: robotName, pluginRobotId: "nao6-ros2", rosbridgeUrl })
    .returning();
  await db.insert(robotStudies).values({ robotId: robot!.id, studyId });
  const snapshot = oneStep([{ id: "hi", type: "say", parameters: { text: "hi" } }]);
  return trialOf(db, { studyId, wizardId, snapshot, withParticipant: true });
}
