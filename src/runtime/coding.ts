// An observer's key press on a code, live: timed here on the trial's clock
// (the browser's clock is not the trial's), checked against a published
// scheme version of the trial's own study, and written to their own tier.
import { eq } from "drizzle-orm";
import type { ClientMessage } from "@/core/socket/messages";
import type { Database } from "@/store/client";
import { pressCode } from "@/store/code-events";
import { trials } from "@/store/schema";

export async function codeLive(
  db: Database,
  by: { trialId: string; observerId: string },
  message: Extract<ClientMessage, { type: "code" }>,
) {
  const [trial] = await db.select({ t0: trials.t0 }).from(trials).where(eq(trials.id, by.trialId));
  if (!trial?.t0)
    return { ok: false as const, reason: "The trial has not started yet: codes are timed from its start." };
  return pressCode(
    db,
    by,
    { versionId: message.schemeVersionId, setId: message.setId, codeId: message.codeId, modifiers: message.modifiers },
    Date.now() - trial.t0.getTime(),
  );
}
