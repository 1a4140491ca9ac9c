// A download written as it is made, a piece at a time, each piece made only
// when the reader asks for it: memory holds one piece, whatever the file's size.
import { logUnexpected } from "@/store/error-reference";

/**
 * The pieces as a body. A failure after the first byte cannot become an
 * error status (the headers have gone): the body is aborted, so the download
 * fails instead of ending as a shorter file that looks complete; the why is
 * logged, the reader is told only what did not finish.
 */
export function textStream(pieces: AsyncIterator<string>, what: string): ReadableStream<Uint8Array> {
  const encoder = new TextEncoder();
  return new ReadableStream<Uint8Array>(
    {
      async pull(controller) {
        try {
          const next = await pieces.next();
          if (next.done) controller.close();
          else controller.enqueue(encoder.encode(next.value));
        } catch (error) {
          logUnexpected(error, what);
          controller.error(new Error(`${what} could not be finished`));
        }
      },
      async cancel() {
        await pieces.return?.();
      },
    },
    // Nothing is read ahead of the reader.
    { highWaterMark: 0 },
  );
}
