import { TRPCError } from "@trpc/server";
import { fetchRequestHandler } from "@trpc/server/adapters/fetch";
import { appRouter } from "@/server/api/root";
import { contextFromHeaders } from "@/server/context";
import { DATABASE_UNAVAILABLE, databaseUnavailable } from "@/store/client";
import { unexpectedResponse } from "@/store/error-reference";
import { LIMITS } from "@/core/network/limits";
import { withinLimit } from "@/server/http/body-limit";

// Someone not signed in can only use the public questionnaire form, so their
// bodies (and the form's, for anyone) are held to the form's small limit; a
// signed-in researcher may send up to an experiment file import.
const onlyForm = (req: Request) =>
  new URL(req.url).pathname
    .replace(/^\/api\/trpc\//, "")
    .split(",")
    .every((path) => path.startsWith("form."));

// Without the database, each call is answered in tRPC's own form (503, the sentence as its message), so the
// page shows the sentence; the body is still read within the public limit, as nobody is known.
const unavailable = (): never => {
  throw new TRPCError({ code: "SERVICE_UNAVAILABLE", message: DATABASE_UNAVAILABLE });
};

async function handler(req: Request) {
  try {
    const context = await contextFromHeaders(req.headers).catch((error: unknown) => {
      if (databaseUnavailable(error)) return null;
      throw error;
    });
    const publicOnly = !context?.user || onlyForm(req);
    const limited = await withinLimit(
      req,
      publicOnly ? LIMITS.publicApi : LIMITS.api,
      publicOnly ? "A request to the public form" : "A request to the API",
    );
    if (limited instanceof Response) return limited;
    return await fetchRequestHandler({
      endpoint: "/api/trpc",
      req: limited,
      router: appRouter,
      createContext: () => context ?? unavailable(),
      maxBatchSize: LIMITS.batchCalls,
    });
  } catch (error) {
    return unexpectedResponse(error, req);
  }
}

export { handler as GET, handler as POST };
