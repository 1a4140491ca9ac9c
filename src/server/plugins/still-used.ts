// The experiments that still use a repository's document of a robot: a
// published version pinned it, or the draft runs it (chose the repository,
// or chose none while it was the robot's default). Named for the sync report
// when the repository stops offering the robot.
import { and, asc, eq, inArray, isNull, or } from "drizzle-orm";
import type { Database } from "@/store/client";
import { experimentVersions, experiments, studies } from "@/store/schema";

export async function experimentsUsing(
  db: Pick<Database, "select">,
  repositoryId: string,
  robotId: string,
  wasDefault: boolean,
): Promise<string[]> {
  const pinned = db
    .select({ id: experimentVersions.experimentId })
    .from(experimentVersions)
    .where(and(eq(experimentVersions.robotId, robotId), eq(experimentVersions.pluginSource, repositoryId)));
  const chosen = wasDefault
    ? or(eq(experiments.pluginSource, repositoryId), isNull(experiments.pluginSource))
    : eq(experiments.pluginSource, repositoryId);
  const rows = await db
    .select({ name: experiments.name, study: studies.title })
    .from(experiments)
    .innerJoin(studies, eq(studies.id, experiments.studyId))
    .where(or(inArray(experiments.id, pinned), and(eq(experiments.robotId, robotId), chosen)))
    .orderBy(asc(studies.title), asc(experiments.name));
  return rows.map((r) => `"${r.name}" (study "${r.study}")`);
}
