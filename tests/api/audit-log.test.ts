// What administrators read under Admin → Audit log: the study's title, who the
// entry is about by name or participant code, and one area at a time.
import { afterAll, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture, newPerson } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
const admin = f.api("admin");
afterAll(close);

it("names the study, the account and the participant an entry is about", async () => {
  const study = await f.newStudy("Handshake study");
  const helper = await newPerson(db, "helper");
  await owner.members.add({ studyId: study.id, email: helper.email, role: "observer" });
  const participant = await owner.participants.create({ studyId: study.id, code: "P-AUDIT" });
  await owner.participants.update({ participantId: participant.id, consentStatus: "given" });
  await admin.admin.users.setRole({ userId: helper.id, role: "wizard" });

  const entries = await admin.admin.auditLog({ limit: 500 });
  expect(entries.find((e) => e.action === "member.add" && e.target === helper.id)).toMatchObject({
    studyTitle: "Handshake study",
    targetName: "helper",
    actor: "owner",
    details: { role: "observer" },
  });
  expect(entries.find((e) => e.action === "participant.consent.given" && e.target === participant.id)).toMatchObject({
    studyTitle: "Handshake study",
    targetName: "P-AUDIT",
  });
  // An account's role is no study's business: no study, and the account by name.
  expect(entries.find((e) => e.action === "user.role" && e.target === helper.id)).toMatchObject({
    studyId: null,
    studyTitle: null,
    targetName: "helper",
    actor: "admin",
  });
  const repository = await admin.plugins.repositories.add({ url: `http://127.0.0.1:9/${crypto.randomUUID()}/` });
  expect((await admin.admin.auditLog({ area: "plugins" })).find((e) => e.target === repository.id)).toMatchObject({
    action: "plugins.repository.add",
    targetName: repository.name,
  });
  // Newest first.
  expect(entries[0]).toMatchObject({ action: "user.role" });
  expect((await admin.admin.auditLog({}))[0]).toMatchObject({ action: "plugins.repository.add" });
});

it("lists one area at a time, and refuses anyone but an administrator", async () => {
  const study = await f.newStudy("Area study");
  await owner.members.add({ studyId: study.id, email: (await newPerson(db, "member")).email, role: "wizard" });
  const members = await admin.admin.auditLog({ area: "member" });
  expect(members.length).toBeGreaterThan(0);
  expect(members.every((e) => e.action.startsWith("member."))).toBe(true);
  const studies = await admin.admin.auditLog({ area: "study" });
  expect(studies.map((e) => e.action)).toContain("study.create");
  expect(studies.every((e) => e.action.startsWith("study."))).toBe(true);
  await expect(admin.admin.auditLog({ area: "everything" as "study" })).rejects.toMatchObject({ code: "BAD_REQUEST" });
  await expect(owner.admin.auditLog({})).rejects.toMatchObject({ code: "FORBIDDEN" });
});
