// The analysis API's route handler: a personal access token (never a sign-in
// cookie), then the endpoint's procedure, then its table as CSV or JSON.
// Every answer that is not a table is JSON { error } in plain words: never
// SQL, a stack or a path (an unexpected failure is logged with a reference).
import { TRPCError } from "@trpc/server";
import { getHTTPStatusCodeFromError } from "@trpc/server/http";
import { chooseFormat, type EndpointName } from "@/core/analysis/api";
import { type Table, tableCsv, tableJson } from "@/core/analysis/table";
import { TOKEN_REFUSALS } from "@/core/access/access-token";
import { failure } from "@/store/error-reference";
import { appRouter } from "../api/root";
import { contextFromToken } from "../tokens/context";

type Caller = ReturnType<typeof appRouter.createCaller>;
type Params = Record<string, string>;

/** Each declared endpoint's procedure: the compiler refuses an endpoint without one. */
const HANDLERS: Record<EndpointName, (api: Caller, p: Params) => Promise<Table>> = {
  studies: (api) => api.analysis.studies(),
  trials: (api, p) => api.analysis.trials({ studyId: p.studyId! }),
  events: (api, p) => api.analysis.events({ studyId: p.studyId! }),
  samples: (api, p) => api.analysis.samples({ studyId: p.studyId! }),
  answers: (api, p) => api.analysis.answers({ studyId: p.studyId! }),
  annotations: (api, p) => api.analysis.annotations({ studyId: p.studyId! }),
  codes: (api, p) => api.analysis.codes({ studyId: p.studyId! }),
  trialEvents: (api, p) => api.analysis.trialEvents({ trialId: p.trialId! }),
};

const NO_STORE = { "cache-control": "no-store" };

const problem = (status: number, message: string, headers: Record<string, string> = {}) =>
  Response.json({ error: message }, { status, headers: { ...NO_STORE, ...headers } });

export async function v1Route(req: Request, name: EndpointName, params: Promise<Params>): Promise<Response> {
  const url = new URL(req.url);
  const request = `${req.method} ${url.pathname}`;
  try {
    const access = await contextFromToken(req.headers, request);
    if ("refused" in access)
      return problem(401, TOKEN_REFUSALS[access.refused], { "www-authenticate": 'Bearer realm="HRIStudio"' });
    const format = chooseFormat(url.searchParams.get("format"), req.headers.get("accept"));
    if (typeof format !== "string") return problem(400, format.error);
    const table = await HANDLERS[name](appRouter.createCaller(access.context), await params);
    return format === "csv"
      ? new Response(tableCsv(table, "script"), { headers: { ...NO_STORE, "content-type": "text/csv; charset=utf-8" } })
      : new Response(tableJson(table), { headers: { ...NO_STORE, "content-type": "application/json" } });
  } catch (error) {
    // A procedure's unexpected failure arrives wrapped as INTERNAL_SERVER_ERROR with the original message.
    if (error instanceof TRPCError && error.code !== "INTERNAL_SERVER_ERROR")
      return problem(getHTTPStatusCodeFromError(error), error.message);
    const { status, message } = failure(error, request);
    return problem(status, message);
  }
}
