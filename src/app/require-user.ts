import { headers } from "next/headers";
import { redirect } from "next/navigation";
import { signedInUser } from "@/server/context";

/** The signed-in person, or a redirect to the sign-in page. */
export async function requireUser() {
  const user = await signedInUser(await headers());
  if (!user) redirect("/sign-in");
  return user;
}
