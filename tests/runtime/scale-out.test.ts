// Two runtime processes on one database: one owns a trial (advisory lock),
// the other relays its events to its own clients through LISTEN/NOTIFY,
// forwards their commands to the owner the same way, and takes the trial over
// when the owner dies.
import type { ChildProcess } from "node:child_process";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { experimentVersions, experiments, studies, studyMembers, trials } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { startRuntime } from "../support/runtime";
import { connectTrial } from "../support/socket";

const SECRET = "scale-out-test-secret".padEnd(40, "x");
const protocol = {
  schemaVersion: 5 as const,
  experiment: { id: "e", name: "E", description: "", robotId: "no-robot" },
  steps: [
    {
      id: "s1",
      name: "Only step",
      description: "",
      actions: [{ id: "a1", type: "wizard_instruction", name: "Smile", parameters: {}, parallelGroup: null }],
    },
  ],
};

describe.sequential("several runtime processes", () => {
  const children: ChildProcess[] = [];
  let trialId = "";
  let a: { url: string; child: ChildProcess };
  let b: { url: string; child: ChildProcess };
  const people: Record<string, string> = {};
  const token = (studyRole: "wizard" | "observer") => signSocketToken({ userId: people[studyRole]!, trialId }, SECRET);

  beforeAll(async () => {
    const url = await freshDatabaseUrl();
    const { db, close } = createDatabase(url);
    for (const role of ["wizard", "observer"])
      people[role] = (
        await createAccount(db, {
          name: role,
          email: `${role}@example.org`,
          password: "password-123",
          role: "researcher",
        })
      ).id;
    const [study] = await db.insert(studies).values({ title: "S", status: "active" }).returning();
    await db.insert(studyMembers).values(
      ["wizard", "observer"].map((role) => ({
        studyId: study!.id,
        userId: people[role]!,
        role: role as "wizard" | "observer",
      })),
    );
    const [experiment] = await db
      .insert(experiments)
      .values({ studyId: study!.id, name: "E", robotId: "no-robot" })
      .returning();
    const [version] = await db
      .insert(experimentVersions)
      .values({ experimentId: experiment!.id, version: 1, snapshot: protocol, hash: "h", robotId: "no-robot" })
      .returning();
    trialId = (
      await db
        .insert(trials)
        .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id })
        .returning()
    )[0]!.id;
    await close();
    a = await startRuntime(url, SECRET);
    b = await startRuntime(url, SECRET);
    children.push(a.child, b.child);
  });
  afterAll(() => children.forEach((c) => c.kill("SIGKILL")));

  it("relays the owner's events to clients of another process, which forwards their commands to it", async () => {
    const wizard = await connectTrial(a.url, token("wizard"));
    const observer = await connectTrial(b.url, token("observer"));
    expect(await wizard.command("r1", { kind: "start" })).toMatchObject({ type: "ack", seqs: [1, 2] });
    expect(await wizard.command("r2", { kind: "note", text: "Participant arrived late" })).toMatchObject({ seqs: [3] });
    await observer.next((m) => m.type === "events" && (m.events as Array<{ seq: number }>).some((e) => e.seq === 3));
    const seen = observer.messages.flatMap((m) =>
      m.type === "events" ? (m.events as Array<{ seq: number }>).map((e) => e.seq) : [],
    );
    expect(seen).toEqual([1, 2, 3]);
    // A wizard whose page reached the other process: the command goes to the owner, which logs and acks it,
    // a long one (in several notifications) with every character as it was written.
    const elsewhere = await connectTrial(b.url, token("wizard"));
    const text = "ça va? 😀 ".repeat(490);
    expect(await elsewhere.command("r3", { kind: "note", text })).toMatchObject({ type: "ack", seqs: [4] });
    const logged = await wizard.next(
      (m) => m.type === "events" && (m.events as Array<{ seq: number }>).some((e) => e.seq === 4),
    );
    expect(JSON.stringify(logged)).toContain(JSON.stringify(text).slice(1, -1));
    wizard.close();
    observer.close();
    elsewhere.close();
  });

  it("lets another process take the trial over when its owner dies", async () => {
    a.child.kill("SIGKILL");
    const wizard = await connectTrial(b.url, token("wizard"), 4);
    let reply: Record<string, unknown> = {};
    for (let i = 0; i < 50; i++) {
      reply = await wizard.command(`t${i}`, { kind: "next" });
      if (reply.type === "ack") break;
      await new Promise((r) => setTimeout(r, 100));
    }
    expect(reply).toMatchObject({ type: "ack", seqs: [5, 6] });
    wizard.close();
  });
});
