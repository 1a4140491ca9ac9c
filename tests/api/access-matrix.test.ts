// Every procedure × every kind of caller, against the real database. The
// expected table is written out by hand: it is the access rules as a person
// states them, checked against what the server actually does.
import { TRPCError } from "@trpc/server";
import { afterAll, describe, expect, it } from "vitest";
import { appRouter } from "../../src/server/api/root";
import { freshDatabase } from "../support/db";
import { buildFixture, CALLERS, type Caller } from "./fixture";
import { ADMIN, baseData, CREATORS, MATRIX, MEMBERS, SIGNED_IN } from "./matrix";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const base = await baseData(f);
afterAll(close);

async function call(caller: Caller, path: string, input: unknown) {
  // As the download routes call: a file procedure answers as it would be downloaded.
  let target: unknown = f.routeApi(caller);
  for (const part of path.split(".")) target = (target as Record<string, unknown>)[part];
  return (target as (i: unknown) => Promise<unknown>)(input);
}

describe("access matrix", () => {
  it("covers every procedure of the API", () => {
    expect(Object.keys(appRouter._def.procedures).sort()).toEqual(Object.keys(MATRIX).sort());
  });

  const cases = Object.entries(MATRIX).flatMap(([path, [allowed]]) =>
    CALLERS.map((caller) => [path, caller, allowed.includes(caller)] as const),
  );

  it.each(cases)("%s by %s → allowed: %s", async (path, caller, allowed) => {
    const input = await MATRIX[path]![1](f, base, caller);
    const outcome = await call(caller, path, input).then(
      () => "ok",
      (e: unknown) => (e instanceof TRPCError ? e.code : `unexpected: ${String(e)}`),
    );
    if (allowed) return expect(outcome).toBe("ok");
    // System operations (no study) refuse plainly; study operations hide the study from non-members.
    const studyScoped = ![SIGNED_IN, ADMIN, CREATORS].includes(MATRIX[path]![0]);
    const denied =
      caller === "anonymous" ? "UNAUTHORIZED" : studyScoped && !MEMBERS.includes(caller) ? "NOT_FOUND" : "FORBIDDEN";
    expect(outcome).toBe(denied);
  });
});
