// Downloads go through the same procedure, and so the same policy, as the API.
import { TRPCError } from "@trpc/server";
import { getHTTPStatusCodeFromError } from "@trpc/server/http";
import { appRouter } from "@/server/api/root";
import { contextFromHeaders } from "@/server/context";

export async function GET(req: Request, { params }: { params: Promise<{ trialId: string }> }) {
  const { trialId } = await params;
  const format = new URL(req.url).searchParams.get("format") === "csv" ? "csv" : "json";
  try {
    const file = await appRouter.createCaller(await contextFromHeaders(req.headers)).trials.export({ trialId, format });
    return new Response(file.body, { headers: { "content-type": file.contentType, "content-disposition": `attachment; filename="${file.filename}"` } });
  } catch (error) {
    if (error instanceof TRPCError) return new Response(error.message, { status: getHTTPStatusCodeFromError(error) });
    throw error;
  }
}
