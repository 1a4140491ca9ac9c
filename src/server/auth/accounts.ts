// Accounts are made by administrators (and the demo seed), not by sign-up.
import { hashPassword } from "better-auth/crypto";
import type { SystemRole } from "@/core/access/policy";
import type { Database } from "@/store/client";
import { account, user } from "@/store/schema";

export interface NewAccount {
  name: string;
  email: string;
  password: string;
  role: SystemRole;
}

/** A user with an email/password credential, hashed the way better-auth checks it (its default scrypt). */
export async function createAccount(db: Database, input: NewAccount) {
  const hash = await hashPassword(input.password);
  const id = crypto.randomUUID();
  return db.transaction(async (tx) => {
    const [created] = await tx
      .insert(user)
      .values({ id, name: input.name, email: input.email.toLowerCase(), role: input.role, emailVerified: true })
      .returning();
    await tx
      .insert(account)
      .values({ id: crypto.randomUUID(), accountId: id, providerId: "credential", userId: id, password: hash });
    return created!;
  });
}
