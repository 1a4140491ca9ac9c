// The sign-in library logs a failed query with the error it got; drizzle's error
// text holds the query's parameters, a session's token among them. A database
// that goes away (dropped here, a real PostgreSQL) must leave no token in the log.
import postgres from "postgres";
import { afterEach, describe, expect, it, vi } from "vitest";
import { createDatabase } from "@/store/client";
import { freshDatabaseUrl, serverUrl } from "../../../tests/support/db";
import { createAccount } from "./accounts";
import { createAuth } from "./auth";

afterEach(() => vi.restoreAllMocks());

describe("the sign-in library's log", () => {
  // Creating and force-dropping a database wait on the server's disk, which a whole suite keeps busy: more time than a test's default.
  it("says a session lookup failed without the session's token", { timeout: 90_000 }, async () => {
    const url = await freshDatabaseUrl();
    const { db, close } = createDatabase(url, { max: 2 });
    const auth = createAuth({
      db,
      secret: "auth-log-test-secret".padEnd(40, "x"),
      baseURL: "http://localhost:3000",
      allowSignUp: false,
      signInPerMinute: 100,
      accountLimit: { failures: 100, windowMinutes: 1 },
    });
    await createAccount(db, {
      name: "Rosa",
      email: "rosa@auth-log.example.org",
      password: "password-123",
      role: "researcher",
    });
    const signedIn = await auth.api.signInEmail({
      body: { email: "rosa@auth-log.example.org", password: "password-123" },
      asResponse: true,
    });
    const cookie = signedIn.headers
      .getSetCookie()
      .map((c) => c.split(";")[0])
      .join("; ");
    const token = decodeURIComponent(/session_token=([^;]+)/.exec(cookie)![1]!).split(".")[0]!;
    expect(token.length).toBeGreaterThan(10);

    const admin = postgres(serverUrl(), { max: 1, onnotice: () => {} });
    await admin.unsafe(`DROP DATABASE ${new URL(url).pathname.slice(1)} WITH (FORCE)`);
    await admin.end();
    const logged: string[] = [];
    for (const level of ["error", "warn", "log", "info"] as const)
      vi.spyOn(console, level).mockImplementation((...args: unknown[]) => {
        logged.push(args.map((a) => (a instanceof Error ? `${a.message} ${String(a.cause)}` : String(a))).join(" "));
      });
    await expect(auth.api.getSession({ headers: new Headers({ cookie }) })).rejects.toBeTruthy();
    expect(logged.join("\n")).not.toContain(token);
    expect(logged.join("\n")).toContain("[sign-in]");
    await close();
  });
});
