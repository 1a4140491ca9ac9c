// One rule for every procedure that answers with a file. The routes outside
// tRPC (downloads) send it as it is made; over tRPC's HTTP link an answer is
// one JSON document, so a streamed text file is read whole there, and a
// streamed binary one (the study zip) cannot be carried at all.
import { TRPCError } from "@trpc/server";
import type { Context } from "./trpc";

type FileBody = string | Uint8Array<ArrayBuffer> | ReadableStream<Uint8Array>;

export async function fileAnswer<File extends { body: FileBody; contentType: string }>(
  ctx: Pick<Context, "streamsFiles">,
  file: File,
): Promise<File> {
  if (!(file.body instanceof ReadableStream) || ctx.streamsFiles) return file;
  if (file.contentType.startsWith("application/zip")) {
    await file.body.cancel();
    throw new TRPCError({ code: "BAD_REQUEST", message: "This file is a download: fetch it from its download link" });
  }
  return { ...file, body: await new Response(file.body).text() };
}
