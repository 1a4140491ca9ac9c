// The server's shared parts for the Next.js process, built once from the environment.
import { readConfig } from "@/store/config";
import { createAuth, type Auth } from "./auth/auth";
import { answered, createDatabase, createSessionClient, type Database } from "@/store/client";
import { configuredMedia } from "./media";
import { appUrl, browserRuntimeUrl } from "./runtime-url";
import type { Context, SignedInUser } from "./api/trpc";
import { SYSTEM_ROLES, type SystemRole } from "@/core/access/policy";
import { channelsOf, transportConfig } from "@/robots/transports/settings";

interface Server {
  db: Database;
  ping: Context["ping"];
  auth: Auth;
  secret: string;
  runtimeUrl: string;
  media: Context["media"];
  robotChannels: Context["robotChannels"];
}

const globalForServer = globalThis as unknown as { hriServer?: Server };

export function server(): Server {
  if (globalForServer.hriServer) return globalForServer.hriServer;
  const config = readConfig();
  if (!config.DATABASE_URL) throw new Error("DATABASE_URL is not set: start the app with `npm start`.");
  if (!config.BETTER_AUTH_SECRET) throw new Error("BETTER_AUTH_SECRET is not set: start the app with `npm start`.");
  const { db } = createDatabase(config.DATABASE_URL);
  const probe = createSessionClient(config.DATABASE_URL);
  const ping = () => probe`select 1`.then(() => undefined);
  const auth = createAuth({
    db,
    secret: config.BETTER_AUTH_SECRET,
    baseURL: appUrl(config),
    allowSignUp: config.HRI_ALLOW_SIGNUP,
    signInPerMinute: config.HRI_SIGNIN_PER_MINUTE,
    accountLimit: {
      failures: config.HRI_SIGNIN_ACCOUNT_FAILURES,
      windowMinutes: config.HRI_SIGNIN_ACCOUNT_WINDOW_MINUTES,
    },
  });
  const runtimeUrl = browserRuntimeUrl(config);
  const media = configuredMedia(config);
  // The runtime reaches the robot with the same settings (src/runtime/main.ts).
  const robotChannels = channelsOf(transportConfig(config));
  globalForServer.hriServer = { db, ping, auth, secret: config.BETTER_AUTH_SECRET, runtimeUrl, media, robotChannels };
  return globalForServer.hriServer;
}

export function toSignedInUser(u: {
  id: string;
  name: string;
  email: string;
  role?: unknown;
  disabled?: unknown;
}): SignedInUser | null {
  if (u.disabled === true) return null;
  const role = SYSTEM_ROLES.includes(u.role as SystemRole) ? (u.role as SystemRole) : "observer";
  return { id: u.id, name: u.name, email: u.email, role };
}

/**
 * Who the request's session belongs to, or null. This is every request's
 * first question to the database, so a database that does not answer (a
 * frozen server keeps its connections open and says nothing) fails it here,
 * with NO_ANSWER, within seconds and before anything of the request was done.
 */
export async function signedInUser(headers: Headers): Promise<SignedInUser | null> {
  const signedIn = await answered(
    server().auth.api.getSession({ headers }),
    "The database did not answer the session lookup.",
  );
  return signedIn ? toSignedInUser(signedIn.user) : null;
}

export async function contextFromHeaders(headers: Headers): Promise<Context> {
  const { db, ping, secret, runtimeUrl, media, robotChannels } = server();
  return { db, ping, user: await signedInUser(headers), secret, runtimeUrl, media, robotChannels };
}
