import { StudyPage } from "@/features/studies/study-page";

export default async function Page({ params }: { params: Promise<{ studyId: string }> }) {
  const { studyId } = await params;
  return <StudyPage studyId={studyId} />;
}
