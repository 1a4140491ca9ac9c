import { v1Route } from "@/server/analysis/v1";

export const GET = (req: Request) => v1Route(req, "studies", Promise.resolve({}));
