// A robot's SSH password is read only from a variable meant for robots: a
// record naming any other (the platform's own secret, its database address)
// is refused as it is saved, registering or changing, with the field named;
// nothing of the refused reference is stored. The form is told which names it
// may give, never a value (who may ask is in the access matrix).
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { robots } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const admin = f.api("admin");
afterAll(close);

const robot = (sshSecret: string) => ({
  name: `NAO ${crypto.randomUUID().slice(0, 8)}`,
  pluginRobotId: "nao6-ros2",
  rosbridgeUrl: "ws://192.0.2.10:9090",
  sshHost: "192.0.2.66",
  sshUser: "nao",
  sshSecret,
});

const notARobotSecret = (name: string) =>
  `Please correct: sshSecret: The SSH secret refers to ${name}, which is not a robot secret; name a variable starting HRI_ROBOT_SECRET_`;

describe("saving a robot's SSH secret by reference", () => {
  it.each(["BETTER_AUTH_SECRET", "DATABASE_URL"])("a reference to %s is refused on register", async (name) => {
    const error = await f.httpError("admin", "robots.register", robot(`env:${name}`));
    expect(error!.data.code).toBe("BAD_REQUEST");
    expect(error!.message).toBe(notARobotSecret(name));
    expect(
      await db
        .select()
        .from(robots)
        .where(eq(robots.sshSecret, `env:${name}`)),
    ).toEqual([]);
  });

  it("a reference to BETTER_AUTH_SECRET is refused when a robot is changed, and the record keeps its own", async () => {
    const saved = await admin.robots.register(robot("env:HRI_ROBOT_SECRET_NAO_A"));
    const error = await f.httpError("admin", "robots.update", {
      ...robot("env:BETTER_AUTH_SECRET"),
      robotId: saved.id,
    });
    expect(error!.message).toBe(notARobotSecret("BETTER_AUTH_SECRET"));
    const [kept] = await db.select().from(robots).where(eq(robots.id, saved.id));
    expect(kept!.sshSecret).toBe("env:HRI_ROBOT_SECRET_NAO_A");
  });

  it("a robot secret and a key file are saved as the references they are", async () => {
    await expect(admin.robots.register(robot("env:HRI_ROBOT_SECRET_PEPPER"))).resolves.toMatchObject({
      sshSecret: "env:HRI_ROBOT_SECRET_PEPPER",
    });
    await expect(admin.robots.register(robot("file:/etc/hristudio/nao.key"))).resolves.toMatchObject({
      sshSecret: "file:/etc/hristudio/nao.key",
    });
  });
});

describe("the names the robot form may give", () => {
  const set = { HRI_ROBOT_SECRET_NAO_WINDOW: "window-password", HRI_ROBOT_SECRET_PEPPER: "pepper-password" };
  beforeAll(() => Object.assign(process.env, set));
  afterAll(() => {
    for (const name of Object.keys(set)) delete process.env[name];
  });

  it("lists the robot variables of the server by name, never a value nor another variable", async () => {
    const names = await admin.robots.secretNames();
    expect(names).toEqual(expect.arrayContaining(Object.keys(set)));
    expect(names.every((n) => n.startsWith("HRI_ROBOT_SECRET_"))).toBe(true);
    expect(JSON.stringify(names)).not.toMatch(/window-password|pepper-password|BETTER_AUTH_SECRET|DATABASE_URL/);
  });
});
