"use client";
// The trial's questionnaires on its analysis page: score first, then every
// answer against the exact version the participant was shown.
import { useQuery } from "@tanstack/react-query";
import { items, type Definition } from "@/core/questionnaires/definition";
import { publishedScores } from "@/core/questionnaires/published-scores";
import { useTRPC } from "@/lib/trpc";
import { Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

export function QuestionnaireAnswers({ trialId, studyId }: { trialId: string; studyId: string }) {
  const trpc = useTRPC();
  const responses = useQuery(trpc.questionnaires.responses.queryOptions({ trialId }));
  if (responses.error) return <Problem error={responses.error} />;
  if (!responses.data?.length) return null;
  return (
    <section aria-label="Questionnaires" className="space-y-3">
      <div className="flex items-center gap-3">
        <h2 className="text-lg font-semibold">Questionnaires</h2>
        <a
          className="ml-auto text-sm font-medium text-brand-600 hover:underline"
          href={`/api/studies/${studyId}/questionnaires`}
        >
          Download all answers of the study (CSV)
        </a>
      </div>
      {responses.data.map((r) => {
        // Only the scores the instrument publishes, by their published names: no overall Godspeed score.
        const definition = r.definition as Definition;
        const scores = publishedScores(definition.instrument ?? null, r.score as Parameters<typeof publishedScores>[1]);
        const composite = scores.find((s) => s.subscale === null);
        const subscales = scores.filter((s) => s.subscale !== null);
        const answers = r.answers as Record<string, unknown>;
        return (
          <Card key={`${r.questionnaire}-${r.submittedAt}`} className="p-4">
            <div className="flex flex-wrap items-baseline gap-3">
              <h3 className="font-semibold">{r.questionnaire}</h3>
              <span className="text-xs text-slate-500">version {r.version}</span>
              {composite && (
                <span className="ml-auto text-lg font-semibold" data-testid="questionnaire-score">
                  Score {Number.isInteger(composite.value) ? composite.value : composite.value.toFixed(2)}
                </span>
              )}
            </div>
            {subscales.length > 0 && (
              <p className="text-sm text-slate-600">
                {subscales.map((s) => `${s.name} ${s.value.toFixed(2)}`).join(" · ")}
              </p>
            )}
            <details className="mt-2 text-sm">
              <summary className="cursor-pointer text-slate-600">Answers</summary>
              <ol className="mt-2 list-decimal space-y-1 pl-5">
                {items(definition).map((item) => (
                  <li key={item.id}>
                    {item.kind === "consent" ? "Consent" : item.text}{" "}
                    <span className="font-medium">→ {formatAnswer(answers[item.id])}</span>
                  </li>
                ))}
              </ol>
            </details>
          </Card>
        );
      })}
    </section>
  );
}

const formatAnswer = (v: unknown) =>
  v === undefined ? "—" : Array.isArray(v) ? v.join(", ") : v === true ? "agreed" : String(v);
