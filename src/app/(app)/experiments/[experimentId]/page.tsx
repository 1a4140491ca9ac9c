import { DesignerPage } from "@/features/designer/designer-page";

export default async function Page({ params }: { params: Promise<{ experimentId: string }> }) {
  const { experimentId } = await params;
  return <DesignerPage experimentId={experimentId} />;
}
