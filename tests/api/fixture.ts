// A study with one member per study role, plus people outside it, for API tests.
import { LocalStorage } from "../../src/server/media/local-storage";
import { fetchRequestHandler } from "@trpc/server/adapters/fetch";
import type { SystemRole } from "../../src/core/access/policy";
import { createCallerFactory, type Context, type SignedInUser } from "../../src/server/api/trpc";
import { appRouter } from "../../src/server/api/root";
import { createAccount } from "../../src/server/auth/accounts";
import type { Database } from "../../src/store/client";
import { eq, sql } from "drizzle-orm";
import { unzipSync } from "fflate";
import { studies, studyMembers, user } from "../../src/store/schema";
import { scratchFolder } from "../support/scratch";

export const CALLERS = ["owner", "researcher", "wizard", "observer", "outsider", "admin", "anonymous"] as const;
export type Caller = (typeof CALLERS)[number];

const SYSTEM_ROLE: Record<Exclude<Caller, "anonymous">, SystemRole> = {
  owner: "researcher",
  researcher: "researcher",
  wizard: "wizard",
  observer: "observer",
  outsider: "researcher",
  admin: "administrator",
};

const callerFactory = createCallerFactory(appRouter);
export const TEST_SECRET = "test-secret-".padEnd(40, "x");
/** The ways to the robot `npm start` opens with no robot settings: the simulated NAO6's rosbridge and SSH. */
export const DEMO_CHANNELS = { rosbridge: true, simulator: true, ssh: true, http: false };

export async function newPerson(db: Database, label: string, role: SystemRole = "researcher"): Promise<SignedInUser> {
  const email = `${label}-${crypto.randomUUID().slice(0, 8)}@example.org`;
  const created = await createAccount(db, { name: label, email, password: "password-123", role });
  return { id: created.id, name: created.name, email: created.email, role };
}

/** One of the accounts the demo seed made (`researcher@demo.hristudio`…), to call the API as. */
export async function demoPerson(db: Database, email: string): Promise<SignedInUser> {
  const [person] = await db.select().from(user).where(eq(user.email, email));
  if (!person) throw new Error(`The demo seed made no account ${email}: seed the demo first.`);
  return { id: person.id, name: person.name, email: person.email, role: person.role };
}

/** Recordings in a throwaway folder, with a small limit so the limit can be tested. */
export function testMedia(maxBytes = 8 * 1024 * 1024): Context["media"] {
  return { storage: new LocalStorage(scratchFolder("media-")), maxBytes };
}

/** The web app asks on a connection of its own (src/server/context.ts); a test's pool does for it. */
export const pingOf = (db: Database) => () => db.execute(sql`select 1`);

export async function buildFixture(db: Database) {
  const people = {} as Record<Exclude<Caller, "anonymous">, SignedInUser>;
  for (const caller of Object.keys(SYSTEM_ROLE) as Array<keyof typeof SYSTEM_ROLE>) {
    people[caller] = await newPerson(db, caller, SYSTEM_ROLE[caller]);
  }
  const media = testMedia();
  const contextOf = (user: SignedInUser | null) => ({
    db,
    ping: pingOf(db),
    user,
    secret: TEST_SECRET,
    runtimeUrl: "ws://127.0.0.1:1",
    media,
    robotChannels: DEMO_CHANNELS,
  });
  const context = (caller: Caller) => contextOf(caller === "anonymous" ? null : people[caller]);
  const api = (caller: Caller) => callerFactory(context(caller));
  /** The API as the routes outside tRPC call it (downloads): a file may come as a stream. */
  const routeApi = (caller: Caller) => callerFactory({ ...context(caller), streamsFiles: true });
  /** The API as anyone else, e.g. the owner of a second study. */
  const apiAs = (user: SignedInUser) => callerFactory(contextOf(user));
  /** An active study (it runs trials) whose members are the four study-role callers. */
  async function newStudy(title = "Fixture study") {
    const created = await api("owner").studies.create({ title });
    const [study] = await db.update(studies).set({ status: "active" }).where(eq(studies.id, created.id)).returning();
    await db.insert(studyMembers).values(
      (["researcher", "wizard", "observer"] as const).map((role) => ({
        studyId: created.id,
        userId: people[role].id,
        role,
      })),
    );
    return study!;
  }
  /** The error a browser would receive for a mutation: the formatted shape, as JSON. */
  async function httpError(caller: Caller, path: string, input: unknown) {
    const res = await fetchRequestHandler({
      endpoint: "/api/trpc",
      req: new Request(`http://test/api/trpc/${path}`, {
        method: "POST",
        body: JSON.stringify(input),
        headers: { "content-type": "application/json" },
      }),
      router: appRouter,
      createContext: () => context(caller),
    });
    const body = (await res.json()) as {
      error?: { message: string; data: { code: string; issues: Array<{ field: string; message: string }> | null } };
    };
    return body.error ?? null;
  }
  return { db, people, api, routeApi, apiAs, newStudy, httpError, media };
}

export type Fixture = Awaited<ReturnType<typeof buildFixture>>;
type Api = ReturnType<typeof callerFactory>;

/** A published one-step experiment (the robot waves) in the study: what most tests need to start a trial. */
export async function publishedVersion(api: Api, studyId: string) {
  const experiment = await api.experiments.create({ studyId, name: "E", robotId: "nao6-ros2" });
  await api.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "S", actions: [{ type: "wave" }] }],
  });
  return { experiment, version: await api.versions.publish({ experimentId: experiment.id }) };
}

/** A consenting participant in a condition running `experimentId`, with a session planned for `wizardId`. */
export async function plannedSession(api: Api, studyId: string, experimentId: string, code: string, wizardId: string) {
  const participant = await api.participants.create({ studyId, code, consentStatus: "given", consentDate: new Date() });
  const condition = await api.conditions.create({ studyId, name: "C", experimentId });
  await api.conditions.assign({ participantId: participant.id, conditionId: condition.id });
  const session = await api.sessions.schedule({ participantId: participant.id, plannedAt: new Date(), wizardId });
  return { participant, session };
}

/** The study's zip read back whole: it is streamed as it is made. */
export async function unzipArchive(archive: { body: ReadableStream<Uint8Array> }) {
  return unzipSync(new Uint8Array(await new Response(archive.body).arrayBuffer()));
}
