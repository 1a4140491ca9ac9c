// A wizard's command that reached a runtime process not running its trial goes
// to the one that does through PostgreSQL NOTIFY, as events come back (see
// relay.ts): every process listens; the owner checks it as it would a command
// on its own socket, carries it out, and answers on a second channel to the
// process that asked. No other broker.
import type postgres from "postgres";
import { oneAfterAnotherBy } from "@/core/one-after-another";
import { answered as within } from "@/store/client";
import type { CommandResult } from "./trial-host";

const REQUESTS = "hri_trial_commands";
const ANSWERS = "hri_trial_answers";
/** Under PostgreSQL's 8,000-byte limit on a notification (the text is ASCII): a larger message goes in parts. */
const PART_CHARS = 7_000;

/** Longer than an owner takes to log a command (its log deadline), so an owner at work is waited for. */
const ANSWER_MS = 5_000;

export interface Forwarded {
  trialId: string;
  userId: string;
  requestId: string;
  retry?: boolean;
  /** The socket command as the wizard sent it (checked again by the owner). */
  command: unknown;
  /** When the wizard asked, on the forwarding process's clock: the owner drops it once too old. */
  askedAt?: number;
}

/** The owner's answer; `halted`: it stopped the robot as it took the command. */
export type ForwardAnswer = CommandResult & { halted?: boolean };

type Request = Forwarded & { id: string; from: string };
type Answer = { id: string; to: string; answer: ForwardAnswer };

export async function commandForwarding(
  sql: postgres.Sql,
  /** Carries out a command of a trial owned here; null: not owned here (another process answers). */
  serve: (request: Forwarded) => Promise<ForwardAnswer | null>,
) {
  const self = crypto.randomUUID();
  const waiting = new Map<string, (answer: ForwardAnswer) => void>();
  const requests = await sql.listen(
    REQUESTS,
    whole<Request>((request) => {
      void serve(request)
        .then((answer) => {
          if (answer) return notify(ANSWERS, { id: request.id, to: request.from, answer } satisfies Answer);
        })
        .catch((error: unknown) => console.error(`[runtime] a forwarded command was not answered: ${String(error)}`));
    }),
  );
  const answers = await sql.listen(
    ANSWERS,
    whole<Answer>(({ id, to, answer }) => {
      if (to === self) waiting.get(id)?.(answer);
    }),
  );
  /** The message in numbered parts ("key index count text"), sent in one statement. */
  const notify = async (channel: string, message: unknown) => {
    // Every character past ASCII escaped, so that a part is cut between characters, never inside one.
    const text = JSON.stringify(message).replace(
      /[\u007f-\uffff]/g,
      (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, "0")}`,
    );
    const key = crypto.randomUUID();
    const count = Math.max(1, Math.ceil(text.length / PART_CHARS));
    const parts = Array.from(
      { length: count },
      (_, i) => `${key} ${i} ${count} ${text.slice(i * PART_CHARS, (i + 1) * PART_CHARS)}`,
    );
    await sql`select pg_notify(${channel}, p) from unnest(${parts}::text[]) as p`;
  };
  // A trial's requests one after another: sent at once, they would go out on several of the pool's connections
  // and reach the owner in any order (a wizard's lines said out of turn). Other trials' go beside them.
  const inTurn = oneAfterAnotherBy<string>();
  return {
    /** The owner's answer, or null when no process answered in time (its owner may have gone). */
    async forward(command: Forwarded): Promise<ForwardAnswer | null> {
      const id = crypto.randomUUID();
      let over = false;
      const answered = new Promise<ForwardAnswer | null>((resolve) => {
        const timer = setTimeout(() => {
          over = true;
          resolve(null);
        }, ANSWER_MS);
        waiting.set(id, (answer) => {
          clearTimeout(timer);
          resolve(answer);
        });
      });
      try {
        // Sent in turn, and waited for no longer than the answer: a request the database does not take in time
        // (a connection caught by a restart) is an owner that did not answer, the requests behind it in the
        // trial's lane go on, and one whose wizard was already told so is never sent. Found by
        // tests/runtime/fencing.test.ts, where a wizard's line after a restart waited for good.
        const sent = inTurn(command.trialId, async () => {
          if (over) return;
          await within(notify(REQUESTS, { ...command, id, from: self } satisfies Request), "Not sent in time.");
        });
        return await Promise.race([sent.then(() => answered), answered]);
      } finally {
        waiting.delete(id);
      }
    },
    close: () => Promise.all([requests.unlisten(), answers.unlisten()]),
  };
}

export type CommandForwarding = Awaited<ReturnType<typeof commandForwarding>>;

/** A listener of messages sent in parts: each is handed on once its last part is in. */
function whole<T>(handle: (message: T) => void) {
  const partial = new Map<string, string[]>();
  return (payload: string) => {
    const [key = "", index = "0", count = "1"] = payload.split(" ", 3);
    const text = payload.slice(key.length + index.length + count.length + 3);
    const parts = partial.get(key) ?? [];
    parts[Number(index)] = text;
    if (parts.filter((p) => p !== undefined).length < Number(count)) return void partial.set(key, parts);
    partial.delete(key);
    handle(JSON.parse(parts.join("")) as T);
  };
}
