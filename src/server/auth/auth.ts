import { betterAuth } from "better-auth";
import { drizzleAdapter } from "better-auth/adapters/drizzle";
import { nextCookies } from "better-auth/next-js";
import type { Database } from "../db/client";
import * as schema from "../db/schema";

export interface AuthSettings {
  db: Database;
  secret: string;
  baseURL: string;
  /** Off by default: an administrator creates accounts. */
  allowSignUp: boolean;
  /** Sign-in attempts allowed per address per minute. */
  signInPerMinute: number;
}

export function createAuth(settings: AuthSettings) {
  return betterAuth({
    appName: "HRIStudio",
    secret: settings.secret,
    baseURL: settings.baseURL,
    database: drizzleAdapter(settings.db, {
      provider: "pg",
      schema: { user: schema.user, session: schema.session, account: schema.account, verification: schema.verification, rateLimit: schema.rateLimit },
    }),
    emailAndPassword: { enabled: true, disableSignUp: !settings.allowSignUp, minPasswordLength: 8 },
    user: {
      additionalFields: {
        // Set by administrators only; a sign-up can never choose its own role.
        role: { type: "string", required: false, defaultValue: "researcher", input: false },
        disabled: { type: "boolean", required: false, defaultValue: false, input: false },
      },
    },
    rateLimit: {
      enabled: true,
      // In the database, so every copy of the app counts the same attempts.
      storage: "database",
      window: 60,
      max: 300,
      customRules: { "/sign-in/email": { window: 60, max: settings.signInPerMinute } },
    },
    databaseHooks: {
      session: {
        create: {
          before: async (session) => {
            const [owner] = await settings.db.query.user.findMany({
              where: (u, { eq }) => eq(u.id, session.userId),
              columns: { disabled: true },
            });
            // A disabled account cannot start a session, whatever its password.
            if (!owner || owner.disabled) return false;
            return { data: session };
          },
        },
      },
    },
    plugins: [nextCookies()],
  });
}

export type Auth = ReturnType<typeof createAuth>;
