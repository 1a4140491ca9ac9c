// A wizard's command that reached a runtime process not running its trial goes
// to the one that does through PostgreSQL NOTIFY, as events come back (see
// relay.ts): every process listens; the owner checks it as it would a command
// on its own socket, carries it out, and answers on a second channel to the
// process that asked. No other broker.
import type postgres from "postgres";
import type { CommandResult } from "./trial-host";

const REQUESTS = "hri_trial_commands";
const ANSWERS = "hri_trial_answers";

/** Longer than an owner takes to log a command (its log deadline), so an owner at work is waited for. */
const ANSWER_MS = 5_000;

export interface Forwarded {
  trialId: string;
  userId: string;
  requestId: string;
  retry?: boolean;
  /** The socket command as the wizard sent it (checked again by the owner). */
  command: unknown;
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
  const requests = await sql.listen(REQUESTS, (payload) => {
    const request = JSON.parse(payload) as Request;
    void serve(request)
      .then((answer) => {
        if (answer) return notify(ANSWERS, { id: request.id, to: request.from, answer } satisfies Answer);
      })
      .catch((error: unknown) => console.error(`[runtime] a forwarded command was not answered: ${String(error)}`));
  });
  const answers = await sql.listen(ANSWERS, (payload) => {
    const { id, to, answer } = JSON.parse(payload) as Answer;
    if (to === self) waiting.get(id)?.(answer);
  });
  const notify = async (channel: string, message: unknown) => {
    await sql`select pg_notify(${channel}, ${JSON.stringify(message)})`;
  };
  return {
    /** The owner's answer, or null when no process answered in time (its owner may have gone). */
    async forward(command: Forwarded): Promise<ForwardAnswer | null> {
      const id = crypto.randomUUID();
      const answered = new Promise<ForwardAnswer | null>((resolve) => {
        const timer = setTimeout(() => resolve(null), ANSWER_MS);
        waiting.set(id, (answer) => {
          clearTimeout(timer);
          resolve(answer);
        });
      });
      try {
        await notify(REQUESTS, { ...command, id, from: self } satisfies Request);
        return await answered;
      } finally {
        waiting.delete(id);
      }
    },
    close: () => Promise.all([requests.unlisten(), answers.unlisten()]),
  };
}

export type CommandForwarding = Awaited<ReturnType<typeof commandForwarding>>;
