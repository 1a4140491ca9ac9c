import { headers } from "next/headers";
import { redirect } from "next/navigation";
import { server, toSessionUser } from "@/server/context";

/** The signed-in person, or a redirect to the sign-in page. */
export async function requireUser() {
  const session = await server().auth.api.getSession({ headers: await headers() });
  const user = session ? toSessionUser(session.user) : null;
  if (!user) redirect("/sign-in");
  return user;
}
