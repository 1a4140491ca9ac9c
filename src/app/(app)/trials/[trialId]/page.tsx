import { TrialPage } from "@/features/execution/trial-page";

export default async function Page({ params }: { params: Promise<{ trialId: string }> }) {
  const { trialId } = await params;
  return <TrialPage trialId={trialId} />;
}
