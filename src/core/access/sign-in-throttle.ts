// The per-account sign-in limit, decided without I/O. Every attempt on an
// account is counted before its password is checked (so a burst of parallel
// guesses cannot all slip in under the limit); a successful sign-in takes back
// its own count only, never the failures other addresses left on the account.

export interface AccountLimit {
  /** Failed sign-ins an account may take inside one window. */
  failures: number;
  windowMinutes: number;
}

/** An account's counter after this attempt was added to it. */
export interface AccountCount {
  failures: number;
  windowStartedAt: Date;
}

/** The `sign_in_throttle` key of an account: its email, as the sign-in form's owner would type it, lower-cased. */
export function accountKey(email: string): string {
  return `account:${email.trim().toLowerCase()}`;
}

/** When a counter started before this instant, its window is over and it starts again. */
export function windowCutoff(now: Date, limit: AccountLimit): Date {
  return new Date(now.getTime() - limit.windowMinutes * 60_000);
}

/** Null when the attempt may go on to the password check; otherwise the message to show. */
export function accountRefusal(count: AccountCount, now: Date, limit: AccountLimit): string | null {
  if (count.failures <= limit.failures) return null;
  const endsAt = count.windowStartedAt.getTime() + limit.windowMinutes * 60_000;
  const minutes = Math.max(1, Math.ceil((endsAt - now.getTime()) / 60_000));
  return `Too many failed sign-ins for this account; try again in ${minutes} minute${minutes === 1 ? "" : "s"}.`;
}
