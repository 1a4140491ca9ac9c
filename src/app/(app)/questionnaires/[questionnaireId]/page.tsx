import { QuestionnaireBuilderPage } from "@/features/questionnaires/builder-page";

export default async function Page({ params }: { params: Promise<{ questionnaireId: string }> }) {
  const { questionnaireId } = await params;
  return <QuestionnaireBuilderPage questionnaireId={questionnaireId} />;
}
