import { server } from "@/server/context";

const handler = (req: Request) => server().auth.handler(req);

export { handler as GET, handler as POST };
