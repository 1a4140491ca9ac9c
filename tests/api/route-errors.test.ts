// An unexpected error in a route reaches the client as one plain sentence with
// a reference, never the error's text (SQL and its parameters, file paths,
// stacks); the server's log has the details under the same reference.
import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { TRPCError } from "@trpc/server";
import { afterAll, afterEach, describe, expect, it, vi } from "vitest";
import { apiRoute } from "../../src/server/api/download";
import { logUnexpected, unexpectedMessage } from "../../src/store/error-reference";
import { ORIGIN, routeServer } from "../support/routes";
import { publishedVersion } from "./fixture";

const s = await routeServer();
afterAll(s.close);
afterEach(() => vi.restoreAllMocks());
const chunks = await import("../../src/app/api/recordings/[recordingId]/chunks/[index]/route");
const owner = await s.signIn("owner");

/** Everything logged to stderr while `run` runs. */
async function logged<T>(run: () => Promise<T>): Promise<{ result: T; log: string }> {
  const lines: string[] = [];
  vi.spyOn(console, "error").mockImplementation((...args: unknown[]) => void lines.push(args.join(" ")));
  const result = await run();
  return { result, log: lines.join("\n") };
}

const REFERENCE = /reference ([0-9a-f]{8})\.$/;

describe("an unexpected error in a route", () => {
  it("answers 500 with a plain message and a reference, and logs the details under it", async () => {
    const sql = `insert into "participants" ("code") values ($1) -- params: ["P-secret"]`;
    const { result: res, log } = await logged(() =>
      apiRoute(new Request(`${ORIGIN}/api/anything`, { headers: owner }), async () => {
        throw new Error(sql);
      }),
    );
    expect(res.status).toBe(500);
    const text = await res.text();
    const ref = REFERENCE.exec(text)![1]!;
    expect(text).toBe(unexpectedMessage(ref));
    expect(text).not.toMatch(/insert|participants|P-secret|at /);
    expect(log).toContain(`[hristudio] error ${ref}: GET /api/anything: `);
    expect(log).toContain(sql);
  });

  it("treats a procedure's wrapped failure (INTERNAL_SERVER_ERROR) the same, and other refusals as before", async () => {
    const { result: res } = await logged(() =>
      apiRoute(new Request(`${ORIGIN}/api/anything`, { headers: owner }), async () => {
        throw new TRPCError({
          code: "INTERNAL_SERVER_ERROR",
          message: 'null value in column "code" violates not-null constraint',
        });
      }),
    );
    expect(res.status).toBe(500);
    expect(await res.text()).toMatch(/^Something went wrong on the server\. .* reference [0-9a-f]{8}\.$/);
    const refused = await apiRoute(new Request(`${ORIGIN}/api/anything`), async () => {
      throw new TRPCError({ code: "FORBIDDEN", message: "Only the study's owner may do this." });
    });
    expect([refused.status, await refused.text()]).toEqual([403, "Only the study's owner may do this."]);
  });

  it("keeps a media store failure's path out of the answer to a recording part", async () => {
    const api = await s.apiAs(owner);
    const study = await s.f.newStudy();
    const { version } = await publishedVersion(api, study.id);
    const trial = await api.trials.create({ versionId: version.id });
    const { recordingId } = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/webm" });
    // A file where the recording's folder should be: the store cannot write.
    mkdirSync(join(process.env.HRI_MEDIA_DIR!, "recordings"), { recursive: true });
    writeFileSync(join(process.env.HRI_MEDIA_DIR!, "recordings", recordingId), "in the way");
    const { result: res, log } = await logged(() =>
      chunks.PUT(
        new Request(`${ORIGIN}/api/recordings/${recordingId}/chunks/0`, {
          method: "PUT",
          headers: { cookie: owner.get("cookie")!, "content-type": "video/webm" },
          body: new Uint8Array([1, 2, 3]),
        }),
        {
          params: Promise.resolve({ recordingId, index: "0" }),
        },
      ),
    );
    expect(res.status).toBe(500);
    const text = await res.text();
    expect(text).not.toContain(process.env.HRI_MEDIA_DIR!);
    expect(log).toContain(`[hristudio] error ${REFERENCE.exec(text)![1]}: PUT /api/recordings/${recordingId}/chunks/0`);
    expect(log).toContain(process.env.HRI_MEDIA_DIR!);
  });

  it("gives each error its own reference", async () => {
    const { result } = await logged(async () => [
      logUnexpected(new Error("a"), "here"),
      logUnexpected(new Error("b"), "here"),
    ]);
    expect(result[0]).not.toBe(result[1]);
  });
});
