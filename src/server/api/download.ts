// File downloads go through the same procedures, and so the same policy and
// blinds, as the API: a refusal becomes the HTTP status with its message.
import { TRPCError } from "@trpc/server";
import { getHTTPStatusCodeFromError } from "@trpc/server/http";
import { contextFromHeaders } from "../context";
import { appRouter } from "./root";

type Caller = ReturnType<typeof appRouter.createCaller>;

export async function download(req: Request, file: (caller: Caller) => Promise<{ body: string | Uint8Array<ArrayBuffer>; contentType: string; filename: string }>): Promise<Response> {
  try {
    const { body, contentType, filename } = await file(appRouter.createCaller(await contextFromHeaders(req.headers)));
    return new Response(body, { headers: { "content-type": contentType, "content-disposition": `attachment; filename="${filename}"` } });
  } catch (error) {
    if (error instanceof TRPCError) return new Response(error.message, { status: getHTTPStatusCodeFromError(error) });
    throw error;
  }
}
