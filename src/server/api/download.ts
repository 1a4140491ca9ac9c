// Routes outside tRPC (file downloads, binary uploads) go through the same
// procedures, and so the same policy and blinds, as the API: a refusal
// becomes the HTTP status with its message. Anything unexpected (a bug, the
// database, the media store) becomes a plain 500 with a reference in the log,
// never the error's own text, which can hold SQL, parameters or paths.
import { TRPCError } from "@trpc/server";
import { getHTTPStatusCodeFromError } from "@trpc/server/http";
import { contextFromHeaders } from "../context";
import { unexpectedResponse } from "@/store/error-reference";
import type { Context } from "./trpc";
import { appRouter } from "./root";

type Caller = ReturnType<typeof appRouter.createCaller>;

export async function apiRoute(
  req: Request,
  handle: (api: Caller, context: Context) => Promise<Response>,
): Promise<Response> {
  try {
    const context = await contextFromHeaders(req.headers);
    return await handle(appRouter.createCaller(context), context);
  } catch (error) {
    // A procedure's unexpected failure arrives wrapped as INTERNAL_SERVER_ERROR with the original message.
    if (error instanceof TRPCError && error.code !== "INTERNAL_SERVER_ERROR")
      return new Response(error.message, { status: getHTTPStatusCodeFromError(error) });
    return unexpectedResponse(error, req);
  }
}

export function download(
  req: Request,
  file: (api: Caller) => Promise<{ body: string | Uint8Array<ArrayBuffer>; contentType: string; filename: string }>,
): Promise<Response> {
  return apiRoute(req, async (api) => {
    const { body, contentType, filename } = await file(api);
    // The length lets the browser show the download's progress.
    const length = typeof body === "string" ? Buffer.byteLength(body) : body.byteLength;
    return new Response(body, {
      headers: {
        "content-type": contentType,
        "content-length": String(length),
        "content-disposition": `attachment; filename="${filename}"`,
      },
    });
  });
}
