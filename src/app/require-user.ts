import { headers } from "next/headers";
import { redirect } from "next/navigation";
import { server, toSignedInUser } from "@/server/context";

/** The signed-in person, or a redirect to the sign-in page. */
export async function requireUser() {
  const signedIn = await server().auth.api.getSession({ headers: await headers() });
  const user = signedIn ? toSignedInUser(signedIn.user) : null;
  if (!user) redirect("/sign-in");
  return user;
}
