// The demo data for a first start: one account per role and a study holding
// the Interactive Storyteller, published, so a newcomer's first trial starts
// at once. Never touches a database that holds data.
import { randomBytes } from "node:crypto";
import { sql } from "drizzle-orm";
import type { SystemRole, StudyRole } from "@/core/access/policy";
import { createAccount } from "../auth/accounts";
import { publish } from "../experiments/publish";
import type { Database } from "@/store/client";
import { actions, experiments, participants, steps, studies, studyMembers, user } from "@/store/schema";
import { STORYTELLER, storytellerDraft } from "./storyteller";

export interface DemoAccount {
  email: string;
  password: string;
  systemRole: SystemRole;
  studyRole: StudyRole | null;
}

const PEOPLE: Array<{ name: string; email: string; systemRole: SystemRole; studyRole: StudyRole | null }> = [
  { name: "Ada Admin", email: "admin@demo.hristudio", systemRole: "administrator", studyRole: null },
  { name: "Rosa Researcher", email: "researcher@demo.hristudio", systemRole: "researcher", studyRole: "owner" },
  { name: "Wim Wizard", email: "wizard@demo.hristudio", systemRole: "wizard", studyRole: "wizard" },
  { name: "Olu Observer", email: "observer@demo.hristudio", systemRole: "observer", studyRole: "observer" },
];

export async function databaseIsEmpty(db: Database): Promise<boolean> {
  const [row] = await db.select({ n: sql<number>`count(*)::int` }).from(user);
  return row!.n === 0;
}

/** Seeds the demo, or returns null if the database already holds users. */
export async function seedDemo(db: Database, password?: string): Promise<DemoAccount[] | null> {
  if (!(await databaseIsEmpty(db))) return null;
  const accounts: DemoAccount[] = [];
  const ids = new Map<string, string>();
  for (const person of PEOPLE) {
    const pw = password ?? randomBytes(9).toString("base64url");
    const created = await createAccount(db, {
      name: person.name,
      email: person.email,
      password: pw,
      role: person.systemRole,
    });
    ids.set(person.email, created.id);
    accounts.push({ email: person.email, password: pw, systemRole: person.systemRole, studyRole: person.studyRole });
  }
  const owner = ids.get("researcher@demo.hristudio")!;

  const experimentId = await db.transaction(async (tx) => {
    const [study] = await tx
      .insert(studies)
      .values({
        title: "Storytelling and memory (demo)",
        description: "A demo study: does the way a robot tells a story change what a listener remembers?",
        status: "active",
        createdBy: owner,
      })
      .returning();
    await tx.insert(studyMembers).values(
      PEOPLE.filter((p) => p.studyRole).map((p) => ({
        studyId: study!.id,
        userId: ids.get(p.email)!,
        role: p.studyRole!,
      })),
    );
    const [experiment] = await tx
      .insert(experiments)
      .values({ ...STORYTELLER, studyId: study!.id, updatedBy: owner })
      .returning();
    const design = storytellerDraft(() => crypto.randomUUID());
    await tx.insert(steps).values(
      design.steps.map((s, position) => ({
        id: s.id,
        experimentId: experiment!.id,
        position,
        name: s.name,
        description: s.description,
      })),
    );
    await tx
      .insert(actions)
      .values(design.steps.flatMap((s) => s.actions.map((a, position) => ({ ...a, stepId: s.id, position }))));
    await tx.insert(participants).values(
      ["P001", "P002", "P003"].map((code) => ({
        studyId: study!.id,
        code,
        consentStatus: "given" as const,
        consentDate: new Date(),
      })),
    );
    return experiment!.id;
  });
  await publish(db, experimentId, owner);
  return accounts;
}
