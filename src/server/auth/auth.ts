import { betterAuth } from "better-auth";
import { drizzleAdapter } from "better-auth/adapters/drizzle";
import { APIError, createAuthMiddleware, isAPIError } from "better-auth/api";
import { nextCookies } from "better-auth/next-js";
import { CLIENT_ADDRESS_HEADER } from "@/core/network/client-address";
import { accountRefusal, type AccountLimit } from "@/core/access/sign-in-throttle";
import type { Database } from "@/store/client";
import * as schema from "@/store/schema";
import { countAttempt, forgiveAttempt } from "./account-throttle";

export interface AuthSettings {
  db: Database;
  secret: string;
  baseURL: string;
  /** Off by default: an administrator creates accounts. */
  allowSignUp: boolean;
  /** Sign-in attempts allowed per address per minute. */
  signInPerMinute: number;
  /** Failed sign-ins allowed per account inside a window, from any addresses. */
  accountLimit: AccountLimit;
}

const SIGN_IN = "/sign-in/email";

export function createAuth(settings: AuthSettings) {
  return betterAuth({
    appName: "HRIStudio",
    logger: {
      // The library logs a failed query with the error it got, whose text holds the query's parameters
      // (a session's token among them): the log keeps its message and the error's code, never that text.
      log: (level, message, ...args) => {
        const codes = args.map((a) => (a as { code?: unknown } | null)?.code).filter((c) => typeof c === "string");
        const line = `[sign-in] ${message}${codes.length ? ` (${codes.join(", ")})` : ""}`;
        if (level === "error") console.error(line);
        else console.warn(line);
      },
    },
    secret: settings.secret,
    baseURL: settings.baseURL,
    database: drizzleAdapter(settings.db, {
      provider: "pg",
      schema: {
        user: schema.user,
        session: schema.login,
        account: schema.account,
        verification: schema.verification,
        rateLimit: schema.rateLimit,
      },
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
      customRules: { [SIGN_IN]: { window: 60, max: settings.signInPerMinute } },
    },
    advanced: {
      // The web server (src/launcher/web-server.ts) sets this header on every
      // request from the socket and the trusted proxies, replacing any value a
      // client sent; X-Forwarded-For as the client wrote it is never read here.
      ipAddress: { ipAddressHeaders: [CLIENT_ADDRESS_HEADER] },
    },
    hooks: {
      // Per account: counted before the password is checked, refused past the
      // limit whatever the password; a success takes back only its own count.
      before: createAuthMiddleware(async (ctx) => {
        const email: unknown = ctx.path === SIGN_IN ? ctx.body?.email : undefined;
        if (typeof email !== "string") return;
        const count = await countAttempt(settings.db, email, settings.accountLimit, new Date());
        const refusal = accountRefusal(count, new Date(), settings.accountLimit);
        if (refusal) throw new APIError("TOO_MANY_REQUESTS", { message: refusal });
      }),
      after: createAuthMiddleware(async (ctx) => {
        const email: unknown = ctx.path === SIGN_IN ? ctx.body?.email : undefined;
        if (typeof email !== "string" || isAPIError(ctx.context.returned)) return;
        await forgiveAttempt(settings.db, email, settings.accountLimit, new Date());
      }),
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
