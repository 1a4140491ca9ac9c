// The largest request bodies the web server accepts. The browser's API client
// reads batchCalls too, so the limits live here rather than in the server.
export const KB = 1024;
export const MB = 1024 * KB;

export const LIMITS = {
  /** Anyone not signed in, and the public questionnaire form: answers to one questionnaire. */
  publicApi: 512 * KB,
  /** The signed-in API; its largest input is an experiment file of up to 2 million characters (up to 3 bytes each). */
  api: 8 * MB,
  /** Sign-in, sign-out and the like: a few short fields. */
  auth: 64 * KB,
  /** Calls in one tRPC batch; the browser's client batches at most this many. */
  batchCalls: 50,
} as const;
