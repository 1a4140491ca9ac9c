import { download } from "@/server/api/download";

export async function GET(req: Request, { params }: { params: Promise<{ studyId: string }> }) {
  const { studyId } = await params;
  return download(req, (api) => api.studies.resultsByConditionCsv({ studyId }));
}
