// The trial socket protocol, both directions, in one versioned file. Every
// message is validated on arrival; anything else is refused with a reason.
import { z } from "zod";

// 2: tokens are single use and carry no role; one hello per connection; the
// server sends "access" when the caller's role or rights change.
export const SOCKET_PROTOCOL_VERSION = 2;

/** Every id a message carries is declared with this, so tests can find them all. */
export const id = z.string().min(1).max(100);
const params = z.record(z.string(), z.unknown());

export const commandSchema = z.discriminatedUnion("kind", [
  z.object({ kind: z.literal("start") }),
  z.object({ kind: z.literal("next") }),
  z.object({ kind: z.literal("skip"), actionId: id.optional() }),
  z.object({ kind: z.literal("trigger"), actionId: id }),
  z.object({ kind: z.literal("answer"), actionId: id, optionId: id }),
  z.object({ kind: z.literal("jump"), stepId: id }),
  z.object({ kind: z.literal("unscripted"), actionType: z.string().min(1).max(200), parameters: params }),
  z.object({ kind: z.literal("pause") }),
  z.object({ kind: z.literal("resume") }),
  z.object({ kind: z.literal("abort"), reason: z.string().max(2000) }),
  z.object({ kind: z.literal("complete") }),
  z.object({ kind: z.literal("emergency_stop") }),
  z.object({ kind: z.literal("note"), text: z.string().min(1).max(5000) }),
  z.object({ kind: z.literal("recording"), recordingId: id, offsetMs: z.number().finite().min(-86_400_000).max(86_400_000) }),
]);

export type WizardCommand = z.infer<typeof commandSchema>;

export const clientMessageSchema = z.discriminatedUnion("type", [
  // First and only once on a connection (the token works once); `lastSeq` asks for exactly what was missed.
  z.object({ type: z.literal("hello"), version: z.literal(SOCKET_PROTOCOL_VERSION), token: z.string().min(1).max(4000), lastSeq: z.number().int().min(0) }),
  z.object({ type: z.literal("command"), requestId: id, command: commandSchema }),
  z.object({ type: z.literal("annotate"), requestId: id, label: z.string().min(1).max(200), note: z.string().max(5000).default("") }),
  z.object({ type: z.literal("ping") }),
]);

export type ClientMessage = z.infer<typeof clientMessageSchema>;

export type ServerMessage =
  // `events` is empty unless the caller may read the log (see mayReadTrialLog);
  // `mayRun`: whether this caller may command this trial now.
  | { type: "welcome"; version: number; trialId: string; role: string; mayRun: boolean; events: unknown[]; viewers: Viewer[] }
  // The caller's role or rights changed while connected (a removed member is disconnected instead).
  | { type: "access"; role: string; mayRun: boolean }
  | { type: "events"; events: unknown[] }
  | { type: "ack"; requestId: string; seqs: number[] }
  | { type: "rejected"; requestId: string | null; reason: string }
  | { type: "presence"; viewers: Viewer[] }
  | { type: "annotation"; annotation: { id: string; relMs: number; label: string; note: string; authorName: string } }
  | { type: "robot"; connected: boolean; detail?: string }
  | { type: "pong" };

export interface Viewer {
  userId: string;
  name: string;
  role: string;
}

export type Parsed = { ok: true; message: ClientMessage } | { ok: false; reason: string };

export function parseClientMessage(raw: string): Parsed {
  let data: unknown;
  try {
    data = JSON.parse(raw);
  } catch {
    return { ok: false, reason: "The message is not valid JSON." };
  }
  const parsed = clientMessageSchema.safeParse(data);
  if (parsed.success) return { ok: true, message: parsed.data };
  const issue = parsed.error.issues[0]!;
  return { ok: false, reason: `The message is not understood: ${issue.path.join(".") || "(message)"}: ${issue.message}` };
}
