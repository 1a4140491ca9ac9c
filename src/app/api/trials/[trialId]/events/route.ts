import { apiRoute } from "@/server/api/download";

/** A trial's log for the analysis page: JSON written as it is read, never parsed and written out again here. */
export const GET = (req: Request, { params }: { params: Promise<{ trialId: string }> }) =>
  apiRoute(req, async (api) => {
    const { trialId } = await params;
    const { body, contentType } = await api.trials.eventsJson({ trialId });
    return new Response(body, { headers: { "content-type": contentType, "cache-control": "no-store" } });
  });
