// The demo study's experiment designed anew and published, as a researcher
// would through the API: what the browser tests run their trials of.
import { DEMO_PASSWORD } from "./app";
import { apiClient, signIn } from "./http";

type Api = ReturnType<typeof apiClient>;
type Steps = Parameters<Api["experiments"]["saveDesign"]["mutate"]>[0]["steps"];

/** A say action as a design holds it. */
export const say = (text: string) => ({ type: "say", name: "", parameters: { text }, parallelGroup: null });

/** Saves `steps` as the demo experiment's design and publishes it; with the study's first participant. */
export async function publishDemoDesign(baseUrl: string, steps: Steps) {
  const researcher = apiClient(baseUrl, await signIn(baseUrl, "researcher@demo.hristudio", DEMO_PASSWORD));
  const [study] = await researcher.studies.mine.query();
  const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
  const draft = await researcher.experiments.get.query({ experimentId: experiment!.id });
  await researcher.experiments.saveDesign.mutate({ experimentId: draft.id, baseRevision: draft.draftRevision, steps });
  const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
  const [participant] = await researcher.participants.list.query({ studyId: study!.id });
  return {
    researcher,
    studyId: study!.id,
    experimentId: experiment!.id,
    versionId: version.id,
    participantId: participant!.id,
  };
}
