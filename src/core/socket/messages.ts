// The trial socket's messages, both directions, in one versioned file that
// the runtime and the browser both import. Every message is validated on
// arrival, at either end; anything else is refused with a reason.
import { z } from "zod";
import type { StoredEvent } from "@/core/trial";

// 2: tokens are single use and carry no role; one hello per connection; the
// server sends "access" when the caller's role or rights change.
// 3: "halted": the robot was stopped, ahead of the stop being logged.
// 4: "signal": live video between the wizard's and observers' browsers (WebRTC), relayed by the runtime;
// each connection has a `peerId` (welcome, presence) and the welcome carries the ICE servers;
// "camera": the robot's own camera, frame by frame.
// Also 4: "code": an observer's key press on a code of a published coding scheme; "codes" answers with their tier's changes.
// 5: the heartbeat (src/core/socket/heartbeat.ts): "ping" carries the page's clock and its last round trip,
// "pong" answers it at once with the ping's time, so each end learns when the other stopped; the runtime's
// own "ping" asks a quiet page to ping at once.
// Also 5: the wizard's "go_on" command ends a pending "Wait for" (src/core/trial/waits.ts).
// Also 5: a "command" carries `at`, the page's clock when the wizard asked (src/core/trial/freshness.ts).
// 6: a long log comes ahead of its "welcome" in "welcome.part" messages; the welcome says how many (welcome.ts).
// Also 6: the page's "camera" says whether it shows the robot's camera now; a page that never says gets it.
export const SOCKET_MESSAGES_VERSION = 6;

/** Every id a message carries is declared with this, so tests can find them all. */
export const id = z.string().min(1).max(100);
const params = z.record(z.string(), z.unknown());

export const commandSchema = z.discriminatedUnion("kind", [
  z.object({ kind: z.literal("start") }),
  z.object({ kind: z.literal("next") }),
  z.object({ kind: z.literal("skip"), actionId: id.optional() }),
  z.object({ kind: z.literal("trigger"), actionId: id }),
  z.object({ kind: z.literal("answer"), actionId: id, optionId: id }),
  z.object({ kind: z.literal("go_on") }),
  z.object({ kind: z.literal("jump"), stepId: id }),
  z.object({ kind: z.literal("unscripted"), actionType: z.string().min(1).max(200), parameters: params }),
  z.object({ kind: z.literal("pause") }),
  z.object({ kind: z.literal("resume") }),
  z.object({ kind: z.literal("abort"), reason: z.string().max(2000) }),
  z.object({ kind: z.literal("complete") }),
  z.object({ kind: z.literal("emergency_stop") }),
  z.object({ kind: z.literal("note"), text: z.string().min(1).max(5000) }),
  // The wizard's browser finished playing a sound the robot cannot play (`failed`: why it could not).
  z.object({ kind: z.literal("played"), actionId: id, failed: z.string().min(1).max(500).optional() }),
  z.object({
    kind: z.literal("recording"),
    recordingId: id,
    offsetMs: z.number().finite().min(-86_400_000).max(86_400_000),
  }),
]);

export type WizardCommand = z.infer<typeof commandSchema>;

// WebRTC's own messages, passed between two browsers as they are: a session
// description (offer or answer) or an ICE candidate. The runtime only relays them.
export const signalSchema = z.discriminatedUnion("kind", [
  z.object({
    kind: z.literal("description"),
    description: z.object({ type: z.enum(["offer", "answer"]), sdp: z.string().max(100_000) }),
  }),
  z.object({
    kind: z.literal("candidate"),
    candidate: z.object({
      candidate: z.string().max(2000),
      sdpMid: z.string().max(100).nullable().optional(),
      sdpMLineIndex: z.number().int().min(0).max(1000).nullable().optional(),
    }),
  }),
]);
export type Signal = z.infer<typeof signalSchema>;

export const clientMessageSchema = z.discriminatedUnion("type", [
  // First and only once on a connection (the token works once); `lastSeq` asks for exactly what was missed.
  z.object({
    type: z.literal("hello"),
    version: z.literal(SOCKET_MESSAGES_VERSION),
    token: z.string().min(1).max(4000),
    // Sequence numbers are stored as 32-bit integers; anything larger cannot be a trial's.
    lastSeq: z
      .number()
      .int()
      .min(0)
      .max(2 ** 31 - 1),
  }),
  // `requestId` is the command's idempotency key: the same id is never carried out twice. `retry`: sent
  // again after a dropped connection, to learn its outcome; never carried out if it did not arrive before.
  // `at`: the page's clock (ms since 1970) when the wizard asked; its freshness counts from then.
  z.object({
    type: z.literal("command"),
    requestId: id,
    command: commandSchema,
    retry: z.boolean().optional(),
    at: z.number().finite().optional(),
  }),
  z.object({
    type: z.literal("annotate"),
    requestId: id,
    label: z.string().min(1).max(200),
    note: z.string().max(5000).default(""),
  }),
  // One key press on a code of a published coding scheme version (of the trial's study), timed by the
  // runtime on the trial's clock: marks a point event, or starts or ends a state (src/core/coding/live.ts).
  z.object({
    type: z.literal("code"),
    requestId: id,
    schemeVersionId: id,
    setId: z.string().min(1).max(100),
    codeId: z.string().min(1).max(100),
    modifiers: z.array(z.string().min(1).max(100)).max(20).default([]),
  }),
  // The heartbeat: `at` is the page's clock (ms since 1970) as it sent it; `roundTripMs`, how long its last
  // ping took to be answered (none before the first answer). The runtime answers at once with a "pong".
  z.object({
    type: z.literal("ping"),
    at: z.number().finite(),
    roundTripMs: z.number().finite().min(0).max(3_600_000).optional(),
  }),
  // Replays the finished trial's robot commands on the simulated robot, from a
  // moment of the trial (ms from t0) at a speed (REPLAY_SPEEDS; checked by the
  // runtime, which says which speeds there are). A connection has one replay:
  // a new one replaces it, and it stops when the connection closes.
  z.object({
    type: z.literal("replay"),
    requestId: id,
    fromMs: z.number().finite().min(0).max(86_400_000),
    speed: z.number().finite(),
  }),
  z.object({ type: z.literal("replay_stop"), requestId: id }),
  // Live video: to another connection of the same trial (its `peerId`), one side of which is the trial's wizard.
  z.object({ type: z.literal("signal"), requestId: id, peerId: id, signal: signalSchema }),
  // Whether this page shows the robot's camera now: a hidden tab or a closed camera panel says `watch: false`
  // and gets no frames (5 a second, each a picture) until it says `true`. A connection starts watching.
  z.object({ type: z.literal("camera"), requestId: id, watch: z.boolean() }),
]);

export type ClientMessage = z.infer<typeof clientMessageSchema>;

/** A stored event as the socket carries it: its time as an ISO string. */
export type WireEvent = StoredEvent<string>;

export const toWire = (event: StoredEvent): WireEvent => ({ ...event, serverTime: event.serverTime.toISOString() });

// The log's own fields are checked; the event inside is the server's engine's
// own output, which the browser folds with the same engine.
const logFields = z.object({
  seq: z.number().int().min(1),
  type: z.string(),
  relMs: z.number().nullable(),
  trialId: id,
  serverTime: z.string(),
  actorId: z.string().nullable(),
});
const wireEvent = z.custom<WireEvent>((e) => logFields.safeParse(e).success, "not a stored event");

/** `peerId` names one connection (a person may watch from two tabs): live video's signals go to it. */
const viewer = z.object({ userId: z.string(), name: z.string(), role: z.string(), peerId: z.string() });

const iceServer = z.object({
  urls: z.array(z.string()),
  username: z.string().optional(),
  credential: z.string().optional(),
});

export const serverMessageSchema = z.discriminatedUnion("type", [
  // The log ahead of its welcome, in parts numbered from 0 (src/core/socket/welcome.ts).
  z.object({ type: z.literal("welcome.part"), part: z.number().int().min(0), events: z.array(wireEvent) }),
  // `events` is empty unless the caller may read the log (see mayReadTrialLog): its last part, after
  // `parts` "welcome.part" messages; `mayRun`: whether this caller may command this trial now.
  z.object({
    type: z.literal("welcome"),
    version: z.literal(SOCKET_MESSAGES_VERSION),
    trialId: id,
    role: z.string(),
    mayRun: z.boolean(),
    events: z.array(wireEvent),
    parts: z.number().int().min(0),
    viewers: z.array(viewer),
    /** This connection, as the others see it in `viewers`. */
    peerId: z.string(),
    /** STUN/TURN servers for live video (HRI_ICE_SERVERS); none on one local network. */
    iceServers: z.array(iceServer),
  }),
  // The caller's role or rights changed while connected (a removed member is disconnected instead).
  z.object({ type: z.literal("access"), role: z.string(), mayRun: z.boolean() }),
  z.object({ type: z.literal("events"), events: z.array(wireEvent) }),
  z.object({ type: z.literal("ack"), requestId: z.string(), seqs: z.array(z.number().int()) }),
  // An emergency stop or abort reached the robot; its "ack" follows once it is logged.
  z.object({ type: z.literal("halted"), requestId: z.string() }),
  z.object({ type: z.literal("rejected"), requestId: z.string().nullable(), reason: z.string() }),
  z.object({ type: z.literal("presence"), viewers: z.array(viewer) }),
  z.object({
    type: z.literal("annotation"),
    annotation: z.object({ id, relMs: z.number(), label: z.string(), note: z.string(), authorName: z.string() }),
  }),
  // The code events a "code" message of this very observer changed (no one else's codes are sent:
  // observers code independently, or their agreement would mean nothing).
  z.object({
    type: z.literal("codes"),
    requestId: z.string(),
    codes: z.array(
      z.object({
        id,
        versionId: id,
        setId: z.string(),
        codeId: z.string(),
        kind: z.enum(["point", "state"]),
        startMs: z.number(),
        endMs: z.number().nullable(),
        modifiers: z.array(z.string()),
        observerId: z.string().nullable(),
      }),
    ),
  }),
  // `name`: the registered robot the trial drives (sent with the welcome, so the wizard sees it before starting).
  z.object({
    type: z.literal("robot"),
    connected: z.boolean(),
    detail: z.string().optional(),
    name: z.string().optional(),
  }),
  // What the robot is doing now (src/core/robots/live-state.ts): sent with the welcome and on every change.
  z.object({
    type: z.literal("robotState"),
    speaking: z.string().nullable(),
    gesture: z.string().nullable(),
    posture: z.string().nullable(),
    battery: z.number().nullable(),
  }),
  // The answer to a "ping": its `at`, so the page measures the round trip.
  z.object({ type: z.literal("pong"), at: z.number() }),
  // To a page the runtime has not heard from lately: ping now (a hidden tab's timers may be held back).
  z.object({ type: z.literal("ping") }),
  // The robot's camera (its plugin's `camera`): one compressed image, base64, as the robot sent it.
  z.object({ type: z.literal("camera"), format: z.string().max(100), data: z.string() }),
  // Live video: a signal from another connection of this trial.
  z.object({ type: z.literal("signal"), peerId: z.string(), signal: signalSchema }),
  // This connection's replay as it goes: started, each command sent, ended or stopped (with why).
  z.object({
    type: z.literal("replay"),
    playing: z.boolean(),
    fromMs: z.number(),
    speed: z.number(),
    /** The trial's moment (ms from t0) the replay has reached. */
    positionMs: z.number(),
    sent: z.number().int(),
    total: z.number().int(),
    /** Commands a replay cannot send again (SSH postures), with why. */
    skipped: z.array(z.string()),
    detail: z.string().optional(),
  }),
]);

export type ServerMessage = z.infer<typeof serverMessageSchema>;
export type Viewer = z.infer<typeof viewer>;

export type Parsed<M> = { ok: true; message: M } | { ok: false; reason: string };

function parseWith<M>(schema: z.ZodType<M>, raw: string): Parsed<M> {
  let data: unknown;
  try {
    data = JSON.parse(raw);
  } catch {
    return { ok: false, reason: "The message is not valid JSON." };
  }
  const parsed = schema.safeParse(data);
  if (parsed.success) return { ok: true, message: parsed.data };
  const issue = parsed.error.issues[0]!;
  return {
    ok: false,
    reason: `The message is not understood: ${issue.path.join(".") || "(message)"}: ${issue.message}`,
  };
}

/** The runtime's check of what a browser sends. */
export const parseClientMessage = (raw: string): Parsed<ClientMessage> => parseWith(clientMessageSchema, raw);

/** The browser's check of what the runtime sends. */
export const parseServerMessage = (raw: string): Parsed<ServerMessage> => parseWith(serverMessageSchema, raw);
