import { server } from "@/server/context";
import { unexpectedResponse } from "@/store/error-reference";
import { LIMITS } from "@/core/network/limits";
import { withinLimit } from "@/server/http/body-limit";

async function handler(req: Request) {
  try {
    const limited = await withinLimit(req, LIMITS.auth, "A sign-in request");
    if (limited instanceof Response) return limited;
    return await server().auth.handler(limited);
  } catch (error) {
    return unexpectedResponse(error, req);
  }
}

export { handler as GET, handler as POST };
