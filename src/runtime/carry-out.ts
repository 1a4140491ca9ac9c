// A wizard's command, already allowed by their access, carried out by the
// trial's host in this process: from the wizard's own socket, or forwarded by
// another process whose socket it came on (forwarding.ts). One path for both.
import { commandVerdict, lostAccess, type TrialAccess } from "@/core/access/trial-socket";
import { parseClientMessage, type ClientMessage } from "@/core/socket/messages";
import { haltsTheRobot } from "@/core/trial";
import { droppedReason, staleness } from "@/core/trial/freshness";
import type { Database } from "@/store/client";
import { logUnexpected } from "@/store/error-reference";
import { type Turn, arrivalOrder } from "@/core/arrival-order";
import { claimTrial, isRecordingOf, loadTrialAccess } from "./access";
import type { ForwardAnswer, Forwarded } from "./forwarding";
import type { CommandResult, TrialHost } from "./trial-host";
import type { TrialHosts } from "./trial-hosts";

export type CommandMessage = Extract<ClientMessage, { type: "command" }>;

/** Carries out a command on its own host once its turn comes; a stop goes at once. */
export async function carryOut(
  db: Database,
  host: TrialHost,
  trialId: string,
  access: TrialAccess,
  message: CommandMessage,
  /** The verdict says this command claims a scheduled trial for its wizard. */
  claim: boolean | undefined,
  /** Told as soon as the robot was stopped (before the stop is logged). */
  halted: () => void,
  /** When the wizard asked, on this process's clock (src/core/trial/freshness.ts). */
  askedAt: number,
  /** Taken as the command arrived: it enters the host's queue after those that arrived before it. */
  turn: Turn,
): Promise<CommandResult & { claimed?: boolean }> {
  try {
    const command =
      message.command.kind === "unscripted" ? { ...message.command, actionId: crypto.randomUUID() } : message.command;
    // A recording is a row of its own: it must belong to this very trial.
    if (command.kind === "recording" && !(await isRecordingOf(db, command.recordingId, trialId)))
      return { ok: false, reason: "That recording belongs to another trial: it was not logged here." };
    let claimed = false;
    if (claim && host.current.status === "scheduled") {
      if (!(await claimTrial(db, trialId, access.userId)))
        return { ok: false, reason: "Another wizard has just claimed this trial: you may watch it but not run it." };
      claimed = true;
    }
    const halting = haltsTheRobot(command.kind);
    // A stop waits for nothing: the host stops the robot ahead of every command it holds.
    if (!halting) await turn.wait();
    if (command.kind === "played") {
      const played = host.browserPlayed(command.actionId, command.failed, access.userId);
      turn.done();
      return await played;
    }
    // Safety before logging: the host stops the robot as it takes the command, whatever the database is doing.
    const logged = host.command(command, access.userId, { id: message.requestId, retry: message.retry, askedAt });
    turn.done();
    // Asked again, a stop halted the robot the first time it arrived, or not at all (the answer says which).
    if (halting && !message.retry) halted();
    const result = await logged.catch((error: unknown) => {
      if (!halting) throw error;
      const ref = logUnexpected(error, "logging a stop");
      return {
        ok: false as const,
        reason: `The robot was stopped, but the stop could not be logged (reference ${ref}).`,
      };
    });
    return { ...result, claimed };
  } finally {
    turn.done();
  }
}

/**
 * How long a command waits for those that arrived before it to enter the queue: one held by a database that
 * does not answer (its access, recording or claim read) stops holding the rest then, and they meet the log's
 * deadline themselves.
 */
export const TURN_WAIT_MS = 3000;

/**
 * Commands other processes forward: carried out if this process runs the trial, checked as on its own socket.
 * A trial's commands are taken in the order they arrived, as on the wizard's own socket: each one's access is
 * read from the database, and those reads may come back in any order.
 */
export function forwardedCommands(db: Database, hosts: TrialHosts) {
  const turnOf = arrivalOrder(TURN_WAIT_MS);
  return async (request: Forwarded): Promise<ForwardAnswer | null> => {
    const turn = turnOf(request.trialId);
    try {
      const checked = await checkForwarded(db, hosts, request);
      if (!checked?.ok) return checked;
      const { host, access, message, claim, askedAt } = checked;
      let halted = false;
      const carried = await carryOut(
        db,
        host,
        request.trialId,
        access,
        message,
        claim,
        () => (halted = true),
        askedAt,
        turn,
      );
      return { ...carried, halted };
    } finally {
      turn.done();
    }
  };
}

/** A forwarded command checked as one on this process's own socket: what carries it out, or the answer at once. */
async function checkForwarded(db: Database, hosts: TrialHosts, request: Forwarded) {
  const host = await hosts.owned(request.trialId);
  if (!host) return null;
  const parsed = parseClientMessage(
    JSON.stringify({ type: "command", requestId: request.requestId, retry: request.retry, command: request.command }),
  );
  if (!parsed.ok || parsed.message.type !== "command")
    return { ok: false as const, reason: parsed.ok ? "That is not a command." : parsed.reason };
  const access = await loadTrialAccess(db, request.trialId, request.userId);
  const lost = access ? lostAccess(access) : "This trial no longer exists.";
  if (lost || !access) return { ok: false as const, reason: lost ?? "" };
  const verdict = commandVerdict(access, parsed.message.command.kind);
  if (!verdict.allow) return { ok: false as const, reason: verdict.reason };
  const askedAt = request.askedAt ?? Date.now();
  const { kind } = parsed.message.command;
  // A sound's end is the browser's report: a fact, never stale.
  const stale = kind === "played" ? null : staleness(kind, askedAt, Date.now());
  if (stale) {
    const reason = droppedReason("forwarding to the runtime running this trial", stale);
    console.warn(`[runtime] trial ${request.trialId}: dropped ${kind}: ${reason}`);
    return { ok: false as const, reason };
  }
  return { ok: true as const, host, access, message: parsed.message, claim: verdict.claim, askedAt };
}
