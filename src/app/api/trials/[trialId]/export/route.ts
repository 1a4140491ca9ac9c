import { download } from "@/server/api/download";

export async function GET(req: Request, { params }: { params: Promise<{ trialId: string }> }) {
  const { trialId } = await params;
  const format = new URL(req.url).searchParams.get("format") === "csv" ? "csv" : "json";
  return download(req, (api) => api.trials.export({ trialId, format }));
}
