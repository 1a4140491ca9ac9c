import { headers } from "next/headers";
import { redirect } from "next/navigation";
import { cache } from "react";
import { signedInUser } from "@/server/context";

// Once per render: the layouts and the page each ask, and all wait on the one lookup (src/proxy.ts
// has already answered 503 if the database did not answer its own).
const sessionUser = cache(async () => signedInUser(await headers()));

/** The signed-in person, or a redirect to the sign-in page. */
export async function requireUser() {
  const user = await sessionUser();
  if (!user) redirect("/sign-in");
  return user;
}
