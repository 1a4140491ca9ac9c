import { download } from "@/server/api/download";

export async function GET(req: Request, { params }: { params: Promise<{ trialId: string }> }) {
  const { trialId } = await params;
  const asked = new URL(req.url).searchParams.get("format");
  const format =
    asked === "csv" || asked === "eaf" || asked === "samples" || asked === "mcap" || asked === "codes" ? asked : "json";
  return download(req, (api) => api.trials.export({ trialId, format }));
}
