import { v1Route } from "@/server/analysis/v1";

export const GET = (req: Request, { params }: { params: Promise<{ studyId: string }> }) =>
  v1Route(req, "codes", params);
