// A study's coding rows for API tests: a published wizard-interventions
// scheme and one code its caller marked in a trial.
import type { Fixture } from "../api/fixture";

type Api = ReturnType<Fixture["api"]>;

export async function codingRows(api: Api, studyId: string, trialId: string) {
  const scheme = await api.coding.createScheme({ studyId, template: "wizard-interventions" });
  const version = await api.coding.publishScheme({ codingSchemeId: scheme.id });
  const code = await api.coding.addCode({
    trialId,
    schemeVersionId: version.id,
    setId: "intervention",
    codeId: "hint",
    startMs: 1500,
  });
  return { codingSchemeId: scheme.id, schemeVersionId: version.id, codeEventId: code.id };
}
