// Two studies on one runtime, for the socket's access tests: each with its own
// people, a published protocol whose ids say which study they belong to, and
// a recording. Trials are made per test, seeded to the state it needs.
import type { ChildProcess } from "node:child_process";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import {
  codingSchemeVersions,
  codingSchemes,
  experimentVersions,
  experiments,
  mediaRecordings,
  studies,
  studyMembers,
  trials,
} from "../../src/store/schema";
import { appendEvents } from "../../src/store/event-store";
import { schemeTemplate } from "../../src/core/coding/templates";
import { signSocketToken } from "../../src/store/socket-token";
import type { EngineEvent } from "../../src/core/trial";
import { freshDatabaseUrl } from "./db";
import { startRuntime } from "./runtime";
import { connectTrial } from "./socket";

export const SECRET = "socket-access-test-secret".padEnd(40, "x");

const protocolOf = (tag: string) => ({
  schemaVersion: 5 as const,
  experiment: { id: `${tag}-experiment`, name: `${tag} experiment`, description: "", robotId: "no-robot" },
  steps: [
    {
      id: `${tag}-step-1`,
      name: "Welcome",
      description: "",
      actions: [
        { id: `${tag}-smile`, type: "wizard_instruction", name: "Smile", parameters: {}, parallelGroup: null },
        {
          id: `${tag}-ask`,
          type: "record_answer",
          name: "Ask",
          parameters: {
            options: [
              { id: `${tag}-yes`, label: "Yes" },
              { id: `${tag}-no`, label: "No" },
            ],
          },
          parallelGroup: null,
        },
      ],
    },
    {
      id: `${tag}-step-2`,
      name: "Goodbye",
      description: "",
      actions: [{ id: `${tag}-wave`, type: "wizard_instruction", name: "Wave", parameters: {}, parallelGroup: null }],
    },
  ],
});

export const STUDY_ROLES_HERE = ["owner", "researcher", "wizard", "otherWizard", "observer"] as const;
export type Person = (typeof STUDY_ROLES_HERE)[number] | "outsider";

export async function socketFixture() {
  const url = await freshDatabaseUrl();
  const { db, close } = createDatabase(url, { max: 4 });
  const studyOf = async (tag: string, people: Record<string, "owner" | "researcher" | "wizard" | "observer">) => {
    const [study] = await db
      .insert(studies)
      .values({ title: `Study ${tag}`, status: "active" })
      .returning();
    const ids: Record<string, string> = {};
    for (const [who, role] of Object.entries(people)) {
      ids[who] = (
        await createAccount(db, {
          name: `${tag} ${who}`,
          email: `${who}@${tag.toLowerCase()}.example.org`,
          password: "password-123",
          role: "researcher",
        })
      ).id;
      await db.insert(studyMembers).values({ studyId: study!.id, userId: ids[who]!, role });
    }
    const [experiment] = await db
      .insert(experiments)
      .values({ studyId: study!.id, name: `${tag} experiment`, robotId: "no-robot" })
      .returning();
    const [version] = await db
      .insert(experimentVersions)
      .values({ experimentId: experiment!.id, version: 1, snapshot: protocolOf(tag), hash: tag, robotId: "no-robot" })
      .returning();
    /** A trial of this study, its events stored before the runtime first opens it. */
    const trial = async (wizardId: string | null, state: "scheduled" | "live" | "completed" = "scheduled") => {
      const live: EngineEvent[] = [
        { type: "trial.started" },
        { type: "step.entered", stepId: `${tag}-step-1`, via: "start" },
      ];
      const events =
        state === "scheduled" ? [] : state === "live" ? live : [...live, { type: "trial.completed" } as const];
      const [row] = await db
        .insert(trials)
        .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id, wizardId })
        .returning();
      await appendEvents(db, { id: row!.id, lastSeq: 0, t0: null }, events, wizardId);
      return row!.id;
    };
    // A published coding scheme of the study, for observers to code with live.
    const [scheme] = await db
      .insert(codingSchemes)
      .values({ studyId: study!.id, name: `${tag} coding`, draft: schemeTemplate("participant-engagement") })
      .returning();
    const [schemeVersion] = await db
      .insert(codingSchemeVersions)
      .values({ schemeId: scheme!.id, version: 1, definition: schemeTemplate("participant-engagement"), hash: tag })
      .returning();
    return { studyId: study!.id, people: ids, trial, schemeVersionId: schemeVersion!.id };
  };
  const a = await studyOf("A", {
    owner: "owner",
    researcher: "researcher",
    wizard: "wizard",
    otherWizard: "wizard",
    observer: "observer",
  });
  const b = await studyOf("B", { owner: "owner", wizard: "wizard" });
  const recording = async (trialId: string) =>
    (
      await db
        .insert(mediaRecordings)
        .values({ trialId, kind: "video", storageKey: `recordings/${trialId}`, mimeType: "video/webm" })
        .returning()
    )[0]!.id;
  const runtime = await startRuntime(url, SECRET);
  const children: ChildProcess[] = [runtime.child];
  const personId = (who: Person) => (who === "outsider" ? b.people.owner! : a.people[who]!);
  return {
    db,
    a,
    b,
    recording,
    personId,
    token: (userId: string, trialId: string) => signSocketToken({ userId, trialId }, SECRET),
    /** Opens a socket to a trial as someone, with a fresh token. */
    open: (who: Person | { userId: string }, trialId: string, lastSeq = 0) =>
      connectTrial(
        runtime.url,
        signSocketToken({ userId: typeof who === "string" ? personId(who) : who.userId, trialId }, SECRET),
        lastSeq,
      ),
    url: runtime.url,
    async stop() {
      for (const c of children) c.kill("SIGKILL");
      await close();
    },
  };
}
