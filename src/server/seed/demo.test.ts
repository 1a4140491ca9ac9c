import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { freshDatabase } from "../../../tests/support/db";
import { actions, experiments, steps, studyMembers } from "@/store/schema";
import { seedDemo } from "./demo";

describe("the demo seed", async () => {
  const { db, close } = await freshDatabase();
  afterAll(close);

  it("creates one account per role and the Storyteller study, with branch targets pointing at real steps", async () => {
    const accounts = await seedDemo(db);
    expect(accounts!.map((a) => a.systemRole)).toEqual(["administrator", "researcher", "wizard", "observer"]);
    expect(new Set(accounts!.map((a) => a.password)).size).toBe(4);
    const [experiment] = await db.select().from(experiments);
    expect(experiment!.name).toBe("Interactive Storyteller");
    const members = await db.select().from(studyMembers).where(eq(studyMembers.studyId, experiment!.studyId));
    expect(members.map((m) => m.role).sort()).toEqual(["observer", "owner", "wizard"]);
    const stepRows = await db.select().from(steps).where(eq(steps.experimentId, experiment!.id));
    const branch = (await db.select().from(actions).where(eq(actions.type, "branch")))[0]!;
    const targets = Object.values((branch.parameters as { targets: Record<string, string> }).targets);
    expect(targets.every((t) => stepRows.some((s) => s.id === t))).toBe(true);
  });

  it("never touches a database that already holds accounts", async () => {
    expect(await seedDemo(db)).toBeNull();
    expect(await db.select().from(experiments)).toHaveLength(1);
  });
});
