// Routes outside tRPC (file downloads, binary uploads) go through the same
// procedures, and so the same policy and blinds, as the API: a refusal
// becomes the HTTP status with its message. Anything unexpected (a bug, the
// database, the media store) becomes a plain 500 with a reference in the log,
// never the error's own text, which can hold SQL, parameters or paths.
import { TRPCError } from "@trpc/server";
import { getHTTPStatusCodeFromError } from "@trpc/server/http";
import { nulPath, nulRefusal } from "@/core/access/input";
import { contextFromHeaders } from "../context";
import { unexpectedResponse } from "@/store/error-reference";
import type { Context } from "./trpc";
import { appRouter } from "./root";

type Caller = ReturnType<typeof appRouter.createCaller>;

export async function apiRoute(
  req: Request,
  handle: (api: Caller, context: Context) => Promise<Response>,
): Promise<Response> {
  // What the query names (a sound's name…) is text like any other: no NUL, which PostgreSQL cannot store.
  const nul = nulPath(Object.fromEntries(new URL(req.url).searchParams));
  if (nul)
    return new Response(nulRefusal(nul), { status: 400, headers: { "content-type": "text/plain; charset=utf-8" } });
  try {
    // A route answers with a Response of its own, which can carry a file as it is made.
    const context: Context = { ...(await contextFromHeaders(req.headers)), streamsFiles: true };
    return await handle(appRouter.createCaller(context), context);
  } catch (error) {
    // A procedure's unexpected failure arrives wrapped as INTERNAL_SERVER_ERROR with the original message.
    if (error instanceof TRPCError && error.code !== "INTERNAL_SERVER_ERROR")
      return new Response(error.message, { status: getHTTPStatusCodeFromError(error) });
    return unexpectedResponse(error, req);
  }
}

type File = {
  body: string | Uint8Array<ArrayBuffer> | ReadableStream<Uint8Array>;
  contentType: string;
  filename: string;
  /** For a file streamed as it is made: how many trials it holds, for the researcher's progress. */
  trials?: number;
};

export function download(req: Request, file: (api: Caller) => Promise<File>): Promise<Response> {
  return apiRoute(req, async (api) => {
    const { body, contentType, filename, trials } = await file(api);
    const headers: Record<string, string> = {
      "content-type": contentType,
      "content-disposition": `attachment; filename="${filename}"`,
    };
    // The length lets the browser show the download's progress; a streamed file's is not known
    // before its end, so it says how many trials are coming instead.
    if (typeof body === "string") headers["content-length"] = String(Buffer.byteLength(body));
    else if (body instanceof Uint8Array) headers["content-length"] = String(body.byteLength);
    if (trials !== undefined) headers["x-export-trials"] = String(trials);
    return new Response(body, { headers });
  });
}
