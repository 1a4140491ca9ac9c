import { AnalysisPage } from "@/features/analysis/analysis-page";

export default async function Page({ params }: { params: Promise<{ trialId: string }> }) {
  const { trialId } = await params;
  return <AnalysisPage trialId={trialId} />;
}
